// vtkKMeansSegmentation: Shlafman et al. 2002 k-means face clustering on the dual graph.
/**
 * @class vtkKMeansSegmentation
 * @brief KMeans Segmentation: Shlafman et al. 2002 k-means face clustering on the dual graph.
 *
 * Representatives start at the face nearest the centroid and then the faces farthest on average
 * from those chosen; faces are assigned by a multi-source Dijkstra on the dual graph with the
 * distance (1 - delta)(1 - cos^2 alpha) + delta Phys, and each patch re-elects the face nearest its
 * centroid until nothing changes.
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
#ifndef vtkKMeansSegmentation_h
#define vtkKMeansSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkKMeansSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkKMeansSegmentation* New();
  vtkTypeMacro(vtkKMeansSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of segments k (at least 1, at most the number of faces). Default 6.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// delta, the weight of the physical distance (divided by its mean). Default 0.2.
  vtkSetMacro(PhysicalWeight, double);
  vtkGetMacro(PhysicalWeight, double);
  ///@}

  ///@{
  /// Assignment and re-election rounds at most. Default 20.
  vtkSetMacro(MaximumIterations, int);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkKMeansSegmentation();
  ~vtkKMeansSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int SegmentCount = 6;
  double PhysicalWeight = 0.2;
  int MaximumIterations = 20;
  char* SegmentArrayName = nullptr;

private:
  vtkKMeansSegmentation(const vtkKMeansSegmentation&) = delete;
  void operator=(const vtkKMeansSegmentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
