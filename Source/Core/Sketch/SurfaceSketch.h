// Strokes, clicks and discs sketched on the visible surface: screen samples taken back to space through a depth image.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <functional>
#include <optional>
#include <vector>

namespace kerf
{

/// What a view shows, pixel by pixel: the depth of the nearest visible surface (a depth buffer:
/// 0 at the near plane, 1 where the background shows) and the map from a pixel and its depth back
/// to space. Pixel (x, y) is the value at index y * width + x, rows from the bottom up, as a depth
/// buffer reads.
class DepthImage
{
public:
  using Unprojection = std::function<Vector3(double x, double y, double depth)>;

  /// The unprojection of a camera: `displayToWorld` maps (x, y, depth, 1) to space in
  /// homogeneous coordinates (divided by the last coordinate), as a renderer's DisplayToWorld
  /// does for its viewport and camera at the moment the matrix is taken.
  static Unprojection projective(const Eigen::Matrix4d& displayToWorld);

  /// Throws kerf::Error when `depth` does not hold width x height values or a size is not positive.
  DepthImage(int width, int height, std::vector<float> depth, Unprojection unproject);

  int width() const { return this->Width; }
  int height() const { return this->Height; }

  /// The depth at (x, y): interpolated bilinearly between the four pixels around it where all four
  /// show the surface, else that of the nearest pixel; nothing off the image or where the
  /// background shows (a depth of 1 or more, or not a number).
  std::optional<double> depth(double x, double y) const;
  /// The surface point under (x, y) at depth(x, y), or nothing where depth() has none.
  std::optional<Vector3> surfacePoint(double x, double y) const;
  /// The length in space of one pixel at depth `depth` under (x, y).
  double pixelSize(double x, double y, double depth) const;

private:
  int Width;
  int Height;
  std::vector<float> Depth;
  Unprojection Unproject;
};

/// How screen samples become points in space.
struct SketchOptions
{
  /// Pixels between the samples that walk a screen segment (a mouse that moves fast still gives a
  /// continuous stroke).
  double step = 1.0;
  /// A step whose length in space exceeds this many pixel sizes crosses a jump in depth (an
  /// occluding contour: the step leaves one part of the surface for another behind or before it).
  /// A step at 85 degrees to the view on a smooth surface is 11.5 pixel sizes long.
  double jumpFactor = 16.0;
};

/// A stroke traced on the visible surface as the mouse moves over it. Each move walks the screen
/// segment from the previous position in steps of options.step pixels: a step on the surface adds
/// its point to the current piece of the stroke, a step onto the background or across a jump in
/// depth ends the piece, and the next step on the surface starts a new one. A stroke that leaves
/// the surface is split, not lost.
class SurfaceStrokeTracer
{
public:
  /// The mouse pressed at (x, y) over `image`, which must outlive the tracer.
  SurfaceStrokeTracer(const DepthImage& image, double x, double y, const SketchOptions& options = SketchOptions());

  /// The mouse is at (x, y).
  void moveTo(double x, double y);
  /// The pieces traced so far, in order: polylines of points on the surface, a piece with a single
  /// sample holding one point.
  const std::vector<std::vector<Vector3>>& pieces() const { return this->Pieces; }
  /// The farthest the mouse has been from where it was pressed, in pixels (a click moves little).
  double reach() const { return this->Reach; }

private:
  void sample(double x, double y);

  const DepthImage& Image;
  SketchOptions Options;
  double StartX, StartY, LastX, LastY;
  double Reach = 0.0;
  bool OnSurface = false;
  bool StartedByJump = false;
  std::vector<std::vector<Vector3>> Pieces;
};

/// The polyline reduced by Douglas and Peucker's (1973) rule: the fewest of its points such that
/// every point left out lies within `tolerance` of the segment that replaces it; the ends stay.
/// Consecutive repeated points are dropped first; a negative or NaN tolerance counts as 0.
std::vector<Vector3> simplifyPolyline(const std::vector<Vector3>& points, double tolerance);

/// A walk over the visible surface under a straight screen segment.
struct SurfaceWalk
{
  double length = 0.0;             ///< the sum of the steps' lengths in space
  Vector3 end = Vector3::Zero();   ///< the last point on the surface
  bool reached = false;            ///< false when the walk left the surface or crossed a jump before the end
  bool started = false;            ///< false when the segment starts off the surface
  double stopX = 0.0, stopY = 0.0; ///< the screen position of the last point on the surface
  double stopDepth = 0.0;          ///< and its depth
};

/// Walks the screen segment from (x0, y0) to (x1, y1) in steps of options.step pixels, summing
/// the steps in space (the length of a way over the visible surface: about the geodesic distance
/// where the screen line follows a geodesic, longer where it bends, and a little short of the
/// surface's length by the chords it sums); stops where the segment leaves the surface or crosses a jump in depth, or
/// once the length reaches `limit`.
SurfaceWalk walkOnSurface(const DepthImage& image, double x0, double y0, double x1, double y1,
  const SketchOptions& options = SketchOptions(), double limit = -1.0);

/// The radius a drag from (x0, y0) to (x1, y1) gives a disc centred under (x0, y0): the length of
/// the walk over the visible surface (walkOnSurface) and, past where the surface ends or turns
/// away behind a contour, the rest of the screen distance at the scale of the walk's last point,
/// so that the radius grows with the drag wherever the mouse goes. 0 when (x0, y0) is off the
/// surface.
double dragRadius(
  const DepthImage& image, double x0, double y0, double x1, double y1, const SketchOptions& options = SketchOptions());

/// The rim of a disc of `radius` around the surface point under (x, y), as it shows on the
/// visible surface: in each of `directions` screen directions, the point where the walk along the
/// surface (walkOnSurface) reaches the radius, or its last point where it leaves the surface first.
/// A closed polyline (the first point is not repeated); empty when (x, y) is off the surface.
std::vector<Vector3> discRim(const DepthImage& image, double x, double y, double radius, int directions = 64,
  const SketchOptions& options = SketchOptions());

/// A stroke drawn on the surface, with its label.
struct DrawnStroke
{
  std::vector<Vector3> points;
  int label = 0;
};

/// Drawn strokes kept as flat lists (as a filter's properties hold them): the points of every
/// stroke one after another, the number of points of each (all the points one stroke when there
/// are no sizes) and each stroke's label (0 for all when there are no labels). Throws kerf::Error
/// when the sizes do not add up to the number of points or one is below 1, or when there are
/// labels but not one per stroke.
std::vector<DrawnStroke> splitDrawnStrokes(
  const std::vector<Vector3>& points, const std::vector<int>& sizes, const std::vector<int>& labels);

} // namespace kerf
