/**
 * @class vtkBoundaryBandCut
 * @brief Boundary Band Cut: each boundary of a segmented surface re-cut within a band around it by a minimum cut that
 * prefers short, concave ways (Katz and Tal 2003).
 *
 * Input: a surface with a cell array of integer labels >= 0 (selected with
 * SetInputArrayToProcess(0, ...); default "Segment"): the output of any segmentation filter, or a
 * labelling drawn by hand. For each pair of neighbouring segments, in label order, the faces of
 * the two within BoundaryBand x sqrt(area of the smaller segment) of their shared boundary
 * (distance along the dual graph's centroid paths) are freed; the faces of the two just outside
 * the band hold the cut to their sides; a minimum cut (Boykov and Kolmogorov 2004) gives each
 * freed face to one side, a cut edge costing its length over the mean edge length divided by 1 +
 * its angular distance over the mean (1 - cos of the bend, times ConvexWeight where convex). A
 * segment inside its own band keeps its boundary. vtkEnsembleSegmentation ends with this step.
 *
 * Output: the surface with the re-cut labels in the cell array of the input's name, numbered 0..
 * by first face, every segment one connected set of faces and no more segments than the input
 * had distinct labels (a label in several pieces is split, and the smallest pieces merged into
 * their neighbours, as every Kerf segmentation ends); with BoundaryBand 0 the labels pass through
 * as given. Field data "SegmentCount", "RecutBoundaries" (pairs of segments whose boundary was
 * re-cut) and "MovedFaces" (faces the cuts gave to the other side).
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): a missing label array, labels that
 * are not integers >= 0, surfaces refused by validation (NaN coordinates, triangles repeating a
 * point, non-manifold edges or vertices, inconsistent orientation), a negative or non-finite
 * BoundaryBand or ConvexWeight.
 * Documentation/filters/AutomaticSegmentation.md has the details and the measurements.
 */
#ifndef vtkBoundaryBandCut_h
#define vtkBoundaryBandCut_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkBoundaryBandCut : public vtkPolyDataAlgorithm
{
public:
  static vtkBoundaryBandCut* New();
  vtkTypeMacro(vtkBoundaryBandCut, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Half-width of the band in which each boundary is re-cut, as a fraction of the square root of
  /// the smaller neighbouring segment's area; 0 leaves the labels as they are. Default 0.4.
  vtkSetMacro(BoundaryBand, double);
  vtkGetMacro(BoundaryBand, double);
  ///@}

  ///@{
  /// How much a convex edge's bend counts against a concave one's (Katz and Tal 2003's eta; 1:
  /// alike). Default 0.1.
  vtkSetMacro(ConvexWeight, double);
  vtkGetMacro(ConvexWeight, double);
  ///@}

protected:
  vtkBoundaryBandCut();
  ~vtkBoundaryBandCut() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double BoundaryBand = 0.4;
  double ConvexWeight = 0.1;

private:
  vtkBoundaryBandCut(const vtkBoundaryBandCut&) = delete;
  void operator=(const vtkBoundaryBandCut&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
