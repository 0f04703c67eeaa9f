// vtkCoreExtractionSegmentation: Segmentation by feature points and core extraction (Katz, Leifman and Tal 2005).
/**
 * @class vtkCoreExtractionSegmentation
 * @brief Core Extraction Segmentation: parts found from prominent feature points and a core
 * (Katz, Leifman and Tal 2005; the survey's section 3.6).
 *
 * The surface is coarsened to CoarseSize samples, embedded in 3D by multidimensional scaling of
 * the samples' geodesic distances (a pose-invariant shape), and its prominent feature points are
 * found on the embedding's convex hull (the largest sum of geodesic distances within
 * FeatureRadius). The core is what lies on the convex hull of the embedding mirrored in its
 * bounding sphere, grown until the feature points lie in different pieces; every piece outside
 * it holding a feature point is a part, and a minimum cut moves each boundary onto the concave
 * creases nearby. The number of parts comes from the shape: no segment count is asked for.
 *
 * Output: the surface with the cell array "Segment" (name is a parameter), one label per
 * triangle numbered 0.. by first face, every segment one connected set of faces; the cell array
 * "Core" (1 where the extracted core lay, before the cuts); field data "SegmentCount",
 * "FeaturePoints", "CoreExtensions" and "FeatureFaces" (the triangles of the feature points).
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): surfaces refused by validation (NaN
 * coordinates, triangles repeating a point, non-manifold edges or vertices, inconsistent
 * orientation), parameters out of range. Documentation/filters/CoreExtractionSegmentation.md has
 * the details.
 */
#ifndef vtkCoreExtractionSegmentation_h
#define vtkCoreExtractionSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkCoreExtractionSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkCoreExtractionSegmentation* New();
  vtkTypeMacro(vtkCoreExtractionSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Samples the coarsening keeps per connected component (farthest-point sampling). Default
  /// 300, at least 10.
  vtkSetMacro(CoarseSize, int);
  vtkGetMacro(CoarseSize, int);
  ///@}

  ///@{
  /// A feature point has the largest sum of geodesic distances within this radius, a fraction of
  /// the geodesic diameter: larger gives fewer, more prominent parts. Default 0.2, in (0, 1].
  vtkSetMacro(FeatureRadius, double);
  vtkGetMacro(FeatureRadius, double);
  ///@}

  ///@{
  /// Points this close to a convex hull, as a fraction of the mirror's radius, count as on it.
  /// Default 0 (the hull's vertices and points on its faces), in [0, 1).
  vtkSetMacro(HullTolerance, double);
  vtkGetMacro(HullTolerance, double);
  ///@}

  ///@{
  /// The core stops growing when a ring brings it closer to the feature points than this fraction
  /// of the initial core's distance to them. Default 0.5, in (0, 1).
  vtkSetMacro(ExtensionFactor, double);
  vtkGetMacro(ExtensionFactor, double);
  ///@}

  ///@{
  /// Smallest part, as a fraction of its component's area; smaller pieces join the core. Default
  /// 0.01, in [0, 1).
  vtkSetMacro(MinimumSegmentArea, double);
  vtkGetMacro(MinimumSegmentArea, double);
  ///@}

  ///@{
  /// Half-width of the band in which a minimum cut moves each boundary, a fraction of the square
  /// root of the smaller segment's area; 0 keeps the coarse boundaries. Default 0.4.
  vtkSetMacro(BandWidth, double);
  vtkGetMacro(BandWidth, double);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkCoreExtractionSegmentation();
  ~vtkCoreExtractionSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int CoarseSize = 300;
  double FeatureRadius = 0.2;
  double HullTolerance = 0.0;
  double ExtensionFactor = 0.5;
  double MinimumSegmentArea = 0.01;
  double BandWidth = 0.4;
  char* SegmentArrayName = nullptr;

private:
  vtkCoreExtractionSegmentation(const vtkCoreExtractionSegmentation&) = delete;
  void operator=(const vtkCoreExtractionSegmentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
