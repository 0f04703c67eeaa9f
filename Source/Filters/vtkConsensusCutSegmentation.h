// vtkConsensusCutSegmentation: Automatic segmentation into k parts by the cuts many concavity-aware harmonic fields
// agree on.
/**
 * @class vtkConsensusCutSegmentation
 * @brief Consensus Cut Segmentation: Automatic segmentation into k parts by the cuts many
 * concavity-aware harmonic fields agree on.
 *
 * Feature points by farthest-point sampling; one factorization of the concavity-aware Laplacian
 * gives every pair of feature points a unit-current harmonic field; the isolines at the peaks of
 * ROI Scissor's score are candidate cuts; candidates that split the surface alike are one consensus
 * cut, ranked by score and by how many fields found it; the best k - 1 compatible cuts make the
 * segments; random walks seeded on each segment's spine then move the cuts onto nearby concave
 * creases (WalkDepth).
 *
 * Output: the surface with the cell array "Segment" (name is a parameter), one label per
 * triangle numbered 0.. by first face, every segment one connected set of faces; field data
 * "SegmentCount" and the method's own figures ("ChosenCuts", "WalkedFaces": the faces the
 * random walks relabelled).
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): surfaces refused by validation (NaN
 * coordinates, triangles repeating a point, non-manifold edges or vertices, inconsistent
 * orientation), a segment count below 1 or above the number of triangles, parameters out of range.
 * Documentation/filters/AutomaticSegmentation.md has the details.
 */
#ifndef vtkConsensusCutSegmentation_h
#define vtkConsensusCutSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkConsensusCutSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkConsensusCutSegmentation* New();
  vtkTypeMacro(vtkConsensusCutSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of segments k (at least 1, at most the number of faces). Default 6.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// Feature points: k plus this many. Default 8.
  vtkSetMacro(ExtraFeaturePoints, int);
  vtkGetMacro(ExtraFeaturePoints, int);
  ///@}

  ///@{
  /// Never more feature points than this (every pair gives a field). Default 16.
  vtkSetMacro(MaximumFeaturePoints, int);
  vtkGetMacro(MaximumFeaturePoints, int);
  ///@}

  ///@{
  /// Cuts leaving a segment below this fraction of the area are refused. Default 0.01.
  vtkSetMacro(MinimumSegmentArea, double);
  vtkGetMacro(MinimumSegmentArea, double);
  ///@}

  ///@{
  /// Boundary refinement: each segment's spine through its faces at least this fraction as deep
  /// as its innermost one seeds random walks on the concavity-aware Laplacian, which move the cuts
  /// onto nearby concave creases; 0 turns it off. Default 0.3.
  vtkSetClampMacro(WalkDepth, double, 0.0, 1.0);
  vtkGetMacro(WalkDepth, double);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkConsensusCutSegmentation();
  ~vtkConsensusCutSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int SegmentCount = 6;
  int ExtraFeaturePoints = 8;
  int MaximumFeaturePoints = 16;
  double MinimumSegmentArea = 0.01;
  double WalkDepth = 0.3;
  char* SegmentArrayName = nullptr;

private:
  vtkConsensusCutSegmentation(const vtkConsensusCutSegmentation&) = delete;
  void operator=(const vtkConsensusCutSegmentation&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
