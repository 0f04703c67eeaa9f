// vtkWatershedSegmentation: Watershed of the edge height 1 - cos(dihedral angle) (Kouhestani 2013, section 3.2).
/**
 * @class vtkWatershedSegmentation
 * @brief Watershed Segmentation: Watershed of the edge height 1 - cos(dihedral angle) (Kouhestani
 * 2013, section 3.2).
 *
 * The watershed on the mesh edges with the height 1 - cos(alpha), alpha the angle between the
 * normals of an edge's faces: minima are flat areas without a lower neighbour, plateaus drain
 * breadth first to their nearest exit, every other edge descends to its lowest neighbour, and each
 * face joins the basin of its lowest edge. Regions are merged, shallowest first, while their
 * watershed depth is below the threshold, or until the segment count remains.
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
#ifndef vtkWatershedSegmentation_h
#define vtkWatershedSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkWatershedSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkWatershedSegmentation* New();
  vtkTypeMacro(vtkWatershedSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Regions whose watershed depth (lowest saddle minus minimum, heights in [0, 2]) is below this
  /// merge into the neighbour across that saddle. Default 0.05.
  vtkSetMacro(DepthThreshold, double);
  vtkGetMacro(DepthThreshold, double);
  ///@}

  ///@{
  /// When positive, merging ignores the threshold and goes on until this many regions remain.
  /// Default 0.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkWatershedSegmentation();
  ~vtkWatershedSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double DepthThreshold = 0.05;
  int SegmentCount = 0;
  char* SegmentArrayName = nullptr;

private:
  vtkWatershedSegmentation(const vtkWatershedSegmentation&) = delete;
  void operator=(const vtkWatershedSegmentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
