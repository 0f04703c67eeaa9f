// SeamCut's seams: streamlines of an anisotropic distance field from a source line, with regrowth and anchoring.
#pragma once

#include "Geodesic/GeodesicPaths.h"
#include "Geodesic/VectorDijkstra.h"

#include <memory>
#include <vector>

namespace kerf
{

class Surface;

struct SeamOptions
{
  /// The metric seams follow (SeamCut, section 2.2: Zhuang et al. 2014 with the normalised
  /// curvature difference); gamma = 0 gives isotropic seams.
  AnisotropicMetricOptions metric;
  int depth = 3; ///< Short-Term Vector Dijkstra's k
};

/// The field of one source line (SeamCut, section 2.2), or of several (the components of one
/// cut) on one connected component: the distance from the lines on their connected component by Short-Term Vector
/// Dijkstra under the metric (by the heat method when gamma = 0, whose gradient is more accurate), its gradient v per
/// triangle and the descent directions v* = -D^-1 v per vertex (Eq. 2). Built once per source
/// line; each seam is then only a streamline, so a new target (seam regrowth, SeamCut section 3)
/// reuses the field. Keeps a reference to the surface, which must outlive it.
class SeamField
{
public:
  /// Throws kerf::Error for a source line that is not on the surface (checkGeodesicSource), no
  /// line, and lines on several connected components.
  SeamField(const Surface& surface, const SurfaceCurve& sourceLine, const SeamOptions& options = SeamOptions());
  SeamField(
    const Surface& surface, const std::vector<SurfaceCurve>& sourceLines, const SeamOptions& options = SeamOptions());

  /// The seam from the source line to `target` (its emitter): the streamline of v* traced from
  /// the target until it meets the line, returned from the line to the target. Throws
  /// kerf::Error for a target off the surface or on another component than the line.
  SurfacePath seam(const SurfacePoint& target) const;

  /// Seam anchoring (SeamCut, section 3): the seam made to meet the source line at `anchor` (moved
  /// to the nearest point of the lines), as the geodesic under the metric from that point to
  /// the emitter `target`.
  SurfacePath anchoredSeam(const SurfacePoint& target, const SurfacePoint& anchor) const;

  /// Distance from the line per vertex (+infinity off its component).
  const std::vector<double>& distance() const { return this->Distance; }
  const std::vector<Vector3>& directions() const { return this->Directions; }
  const std::vector<SurfaceCurve>& sourceLines() const { return this->SourceLines; }
  const SeamOptions& options() const { return this->Options; }

private:
  const Surface& TheSurface;
  std::vector<SurfaceCurve> SourceLines;
  SeamOptions Options;
  int Component = -1;
  std::vector<double> Distance;
  std::vector<Vector3> Directions;
};

/// The seams of one surface: the field of the last source lines and options is kept, so that a
/// new target (seam regrowth) or a new anchor costs one streamline, and only new lines or
/// options compute a field. A session for filters (SurfaceInput::SessionFor). Not thread-safe.
class SeamSession
{
public:
  explicit SeamSession(std::shared_ptr<const Surface> surface);

  const Surface& surface() const { return *this->SurfacePointer; }

  /// The field of these lines and options: the kept one when both equal the last call's
  /// (`reused` set to true), else a new one (SeamField's errors).
  const SeamField& field(
    const std::vector<SurfaceCurve>& sourceLines, const SeamOptions& options, bool* reused = nullptr);

private:
  std::shared_ptr<const Surface> SurfacePointer;
  std::unique_ptr<SeamField> Field;
};

} // namespace kerf
