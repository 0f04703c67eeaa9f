// Analytic test surfaces: sphere, torus, cylinder, plane, with known curvature and harmonic functions.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <functional>
#include <vector>

namespace kerf
{

/// Icosahedron subdivided `levels` times, projected to a sphere of the given radius and centred at
/// the origin: 10 * 4^levels + 2 vertices, 20 * 4^levels triangles, closed, outward oriented.
TriangleMesh makeIcosphere(double radius, int levels);

/// Torus around the z axis with tube centre radius `majorRadius` and tube radius `minorRadius`;
/// `around` x `tube` vertices on a regular parameter grid, 2 * around * tube triangles, closed.
/// Vertex (i, j) sits at angle 2 pi i / around about z and 2 pi j / tube about the tube.
TriangleMesh makeTorus(double majorRadius, double minorRadius, int around, int tube);

/// Open cylinder of the given radius around the z axis from z = 0 to z = height, with `around`
/// vertices per ring and `rings` rings (two boundary loops), outward oriented.
TriangleMesh makeCylinder(double radius, double height, int around, int rings);

/// makeCylinder with `bumps` round bumps evenly spaced around z (the first on the +x axis) at
/// height `bumpHeight`: a point at distance d (measured on the unrolled cylinder) from the nearest
/// bump's centre moves outward by bumpSize * (1 - (d / bumpRadius)^2)^2 where d < bumpRadius.
TriangleMesh makeBumpyCylinder(double radius, double height, int around, int rings, int bumps, double bumpHeight,
  double bumpRadius, double bumpSize);

/// makeCylinder with each point moved outward by offset(u, z) (u the angle around z in
/// (-pi, pi], z the height; negative moves it inward): knobs, ridges, grooves and creases on a tube.
TriangleMesh makeReliefCylinder(
  double radius, double height, int around, int rings, const std::function<double(double u, double z)>& offset);

/// The features of the geometry seam carving tests, on a tube of radius 1 from z = 0 to z = 5
/// (handle z <= 0.8, fixed z >= 4.2 with heightBandRegions, so the modeling region is 3.4 high):
/// Knob: a round bump of height 0.35 and radius 0.45 at z = 2 (a ring can pass above or below);
/// Groove: a round groove of depth 0.15 and half-width 0.2 all around at z = 2.5; Crease: a sharp
/// ridge 0.08 high, 0.2 wide, all around at z = 2.2 (three creases); Cups: three suction-cup-like
/// bumps (a rim of height 0.12 around a dip, radius 0.3) in a row at z = 1.5, 2.3, 3.1; Ridge: a
/// ridge 0.2 high along the whole tube (no ring can avoid it).
enum class TubeFeature
{
  Knob,
  Groove,
  Crease,
  Cups,
  Ridge
};
TriangleMesh makeFeatureTube(TubeFeature feature, int around, int rings);

/// The points of a makeFeatureTube surface off the plain tube (radius differs from 1 by > 1e-3)
/// in the modeling region z in (0.8, 4.2): the feature's points.
std::vector<int> featureTubePoints(const TriangleMesh& mesh);

/// Per-vertex seam-carving regions along z (Dekkers and Kobbelt 2014, 3.1): 2 (handle) where
/// z <= handleTop, 0 (fixed) where z >= fixedBottom, 1 (modeling) between.
std::vector<double> heightBandRegions(const TriangleMesh& mesh, double handleTop, double fixedBottom);

/// Planar grid over [0, width] x [0, height] in z = 0 with (columns + 1) x (rows + 1) vertices,
/// each quad split along its diagonal. Vertex (i, j) has index j * (columns + 1) + i.
TriangleMesh makeGrid(double width, double height, int columns, int rows);

/// makeGrid over [0, cells]^2 with every interior point moved by up to `jitter` cells in x and y
/// (uniformly, from a std::mt19937 seeded with `seed`): obtuse triangles whose cotangent
/// Laplacian is not linearly precise, for the intrinsic Delaunay weighting's tests.
TriangleMesh makeJitteredGrid(int cells, double jitter, unsigned seed);

/// A cylinder cut open along a line: makeGrid(2 pi radius, height, around, rings) wrapped around
/// the z axis (grid point (x, y) to angle x / radius, height y), its first and last columns at the
/// same positions but distinct vertices. A disk whose quads are planar rectangles: it unrolls
/// onto the grid without distortion.
TriangleMesh makeSlitCylinder(double radius, double height, int around, int rings);

/// A sector of the cone with apex at the origin, axis z and half-angle `halfAngle`: makeGrid over
/// distances [innerDistance, outerDistance] from the apex and angles [0, angle] about z,
/// `columns` x `rows` cells. A disk whose quads are planar trapezoids (two rulings through the
/// apex span a plane): it unrolls without distortion.
TriangleMesh makeConeSector(
  double halfAngle, double innerDistance, double outerDistance, double angle, int columns, int rows);

/// Per triangle, the octant of its centroid (1 if x > 0, plus 2 if y > 0, plus 4 if z > 0): chart
/// labels for tests, eight disks on a sphere centred at the origin.
std::vector<int> octantLabels(const TriangleMesh& mesh);

/// Two lobes joined by a neck: an icosphere (`levels` subdivisions) stretched along z to
/// [-halfLength, halfLength], with radius `lobeRadii[0]` below the neck and `lobeRadii[1]` above
/// it (blended smoothly), pinched by the factor (1 - neckDepth) around z = neckHeight. A surface
/// of revolution about the z axis, closed and outward oriented, with a concave neck.
TriangleMesh makeDumbbell(
  double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth, int levels);

/// A sphere of radius 1 (an icosphere with `levels` subdivisions) with `count` fingers in the
/// xy plane, evenly spaced around z from the +x axis: a point at angle alpha from the nearest
/// finger's axis moves out to radius 1 + length * exp(-(alpha / width)^4), a flat-topped finger
/// with a concave crease where it leaves the sphere. Closed and outward oriented.
TriangleMesh makeProtrusions(int count, double length, double width, int levels);

/// The radius of makeDumbbell's surface at height z (the profile it is built from).
double dumbbellRadius(
  double z, double halfLength, const std::array<double, 2>& lobeRadii, double neckHeight, double neckDepth);

} // namespace kerf
