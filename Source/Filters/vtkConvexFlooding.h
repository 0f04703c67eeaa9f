// vtkConvexFlooding: Convex patches flooded across the dual graph (Kouhestani 2013, section 3.1).
/**
 * @class vtkConvexFlooding
 * @brief Convex Flooding: Convex patches flooded across the dual graph (Kouhestani 2013, section
 * 3.1).
 *
 * Flooding of the dual graph while the patch stays convex: a face joins when every edge it shares
 * with the patch has an interior dihedral angle of at most pi + epsilon; global convexity failures
 * are not tested. Patches smaller than q times the total area are then merged into their largest
 * neighbour, and, with a segment count, on down to that many.
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
#ifndef vtkConvexFlooding_h
#define vtkConvexFlooding_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkConvexFlooding : public vtkPolyDataAlgorithm
{
public:
  static vtkConvexFlooding* New();
  vtkTypeMacro(vtkConvexFlooding, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// epsilon in radians: interior dihedral angles up to pi + epsilon count as convex. Default 0.1.
  vtkSetMacro(AngleTolerance, double);
  vtkGetMacro(AngleTolerance, double);
  ///@}

  ///@{
  /// q: patches below q times the total area merge into their largest neighbour. Default 0.01.
  vtkSetMacro(MinimumAreaFraction, double);
  vtkGetMacro(MinimumAreaFraction, double);
  ///@}

  ///@{
  /// When positive, merging goes on until at most this many segments remain. Default 0 (no limit).
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkConvexFlooding();
  ~vtkConvexFlooding() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double AngleTolerance = 0.1;
  double MinimumAreaFraction = 0.01;
  int SegmentCount = 0;
  char* SegmentArrayName = nullptr;

private:
  vtkConvexFlooding(const vtkConvexFlooding&) = delete;
  void operator=(const vtkConvexFlooding&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
