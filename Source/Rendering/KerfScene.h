// Renders a Kerf result to an image: a surface coloured by an array, optional direction strokes.
#pragma once

#include "KerfRenderingModule.h"

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderWindow;

namespace kerf
{

/// How a scene is drawn.
struct SceneOptions
{
  /// Point or cell array that colours the surface ("" for a plain surface).
  std::string colorArray;
  /// Diverging (blue-white-red, symmetric about 0) for signed values such as curvature;
  /// Sequential for non-negative values; Categorical for integer labels.
  enum class ColorMap
  {
    Diverging,
    Sequential,
    Categorical
  };
  ColorMap colorMap = ColorMap::Diverging;
  /// The colour range covers this fraction of the values (robust to outliers); 1 for all.
  double rangeFraction = 0.95;
  /// If > 0, a diverging map spans [-symmetricRange, symmetricRange] instead.
  double symmetricRange = 0.0;
  /// Point vector array drawn as short strokes on the surface ("" for none).
  std::string directionArray;
  /// Approximate number of strokes.
  int directionCount = 3000;
  /// Title shown above the colour legend.
  std::string legendTitle;
  /// Number of isolines of the colour array drawn over the surface (point arrays; 0 for none).
  int isolineCount = 0;
  /// Extra geometry drawn over the surface: lines as tubes of the given width (pixels), points
  /// as round sprites of that size.
  struct Overlay
  {
    vtkSmartPointer<vtkPolyData> data;
    std::array<double, 3> color{ { 0.0, 0.0, 0.0 } };
    double width = 3.0;
  };
  std::vector<Overlay> overlays;
  /// Caption drawn in the top-left corner.
  std::string caption;
  int width = 900;
  int height = 700;
  /// Camera rotation from the default view, in degrees. The default view looks down -z with +y
  /// up; with `frameLongestAxis`, it looks along the bounding box's shortest axis with the
  /// longest one up, which shows most of an arbitrarily oriented model.
  double azimuth = 30.0;
  double elevation = 20.0;
  bool frameLongestAxis = false;
  /// Camera zoom after fitting the surface.
  double zoom = 1.25;
  /// For categorical cell colouring: draw the boundaries between differently labelled cells.
  bool outlineSegments = true;
  /// Render offscreen (no window appears).
  bool offscreen = true;
  /// If > 0: the surface is textured with a checkerboard of this many squares per side of the
  /// unit texture square, through its texture coordinates (an error if it has none).
  int checkerboardSquares = 0;
};

/// Builds and renders the scene. Returns nullptr and sets `error` if the colour or direction
/// array is missing.
KERFRENDERING_EXPORT vtkSmartPointer<vtkRenderWindow> RenderScene(
  vtkPolyData* surface, const SceneOptions& options, std::string& error);

/// Two views of one surface side by side with a shared camera, for example a method's
/// segmentation beside a human's. The window takes the left options' size; each view gets half.
KERFRENDERING_EXPORT vtkSmartPointer<vtkRenderWindow> RenderSideBySide(
  vtkPolyData* surface, const SceneOptions& left, const SceneOptions& right, std::string& error);

/// Two surfaces side by side, each with its own camera (a textured surface beside its texture
/// layout, for example). The window takes the left options' size; each view gets half.
KERFRENDERING_EXPORT vtkSmartPointer<vtkRenderWindow> RenderPair(vtkPolyData* leftSurface, const SceneOptions& left,
  vtkPolyData* rightSurface, const SceneOptions& right, std::string& error);
/// A harmonic cut in two views: on the left the field "HarmonicField" with isolines, the stroke
/// (green) and its constraint points (yellow); on the right the cell array "Segment" and the cut
/// curve (red). 1200 x 600 pixels.
KERFRENDERING_EXPORT vtkSmartPointer<vtkRenderWindow> RenderCutScene(vtkPolyData* labelledSurface, vtkPolyData* stroke,
  vtkPolyData* constraints, vtkPolyData* cut, const std::string& caption, std::string& error);

/// Writes the window's image as PNG; false and `error` on failure.
KERFRENDERING_EXPORT bool WritePNG(vtkRenderWindow* window, const std::string& fileName, std::string& error);

} // namespace kerf
