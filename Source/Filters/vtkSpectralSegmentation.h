// vtkSpectralSegmentation: Liu and Zhang 2004 spectral clustering of faces, on a coarsened patch graph.
/**
 * @class vtkSpectralSegmentation
 * @brief Spectral Segmentation: Liu and Zhang 2004 spectral clustering of faces, on a coarsened
 * patch graph.
 *
 * The faces are first grouped into patches by hierarchical face clustering; the dense affinity
 * exp(-Dist / 2 sigma^2) of geodesic and angular distance is formed on the patches, normalised, and
 * its k leading eigenvectors embed the patches on a sphere where k-means clusters them; each face
 * takes its patch's segment.
 *
 * Output: the surface with the cell array "Segment" (name is a parameter), one label per
 * triangle numbered 0.. by first face, every segment one connected set of faces; field data
 * "SegmentCount" and the method's own figures.
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): surfaces refused by validation (NaN
 * coordinates, triangles repeating a point, non-manifold edges or vertices, inconsistent
 * orientation), a segment count below 1 or above the number of triangles, parameters out of range.
 * Documentation/filters/AutomaticSegmentation.md has the details.
 */
#ifndef vtkSpectralSegmentation_h
#define vtkSpectralSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkSpectralSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkSpectralSegmentation* New();
  vtkTypeMacro(vtkSpectralSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of segments k (at least 1, at most the number of faces). Default 6.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// delta, the weight of the geodesic distance. Default 0.03.
  vtkSetMacro(GeodesicWeight, double);
  vtkGetMacro(GeodesicWeight, double);
  ///@}

  ///@{
  /// eta, the weight of the angular distance on convex edges (concave edges use 1). Default 0.2.
  vtkSetMacro(ConvexAngleWeight, double);
  vtkGetMacro(ConvexAngleWeight, double);
  ///@}

  ///@{
  /// Size of the dense affinity: the faces are coarsened to this many patches. Default 400.
  vtkSetMacro(PatchCount, int);
  vtkGetMacro(PatchCount, int);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkSpectralSegmentation();
  ~vtkSpectralSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int SegmentCount = 6;
  double GeodesicWeight = 0.03;
  double ConvexAngleWeight = 0.2;
  int PatchCount = 400;
  char* SegmentArrayName = nullptr;

private:
  vtkSpectralSegmentation(const vtkSpectralSegmentation&) = delete;
  void operator=(const vtkSpectralSegmentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
