/**
 * @class vtkRegionGrowing
 * @brief Region growing from labelled strokes under the improved isophotic metric (Ji et al. 2006, section 4.2).
 *
 * The first half of Easy Mesh Cut, for pipelines that refine or inspect the grown parts on their
 * own (vtkRegionGrowing -> vtkSnakeRefinement gives what vtkEasyMeshCut gives in one step). Each
 * stroke (a polyline of input 1, or a point of a vertex cell: a click) carries a label in the cell array
 * named by StrokeLabelArrayName. Every vertex takes the label of the stroke nearest to it under
 * the improved isophotic metric (sections 3 and 4.2), a length that grows with the change of the
 * normal and, strongly, with concave curvature, so parts meet along concave creases. A triangle
 * takes the label two or three of its corners share; one whose three corners differ takes the
 * label of the corner nearest to its stroke.
 *
 * Output 0: the surface with the point and cell arrays SegmentArrayName (the label of each vertex
 * and triangle, -1 where no stroke reaches: a component without strokes) and the point array
 * "IsophoticDistance" (the metric distance to the nearest stroke, -1 where none reaches), field
 * data "UnreachableVertices". Output 1: the boundaries between labels along mesh edges, as
 * polylines with the cell arrays Length, Closed, LeftLabel and RightLabel (the smaller label on
 * the left seen from outside).
 *
 * Errors (vtkErrorMacro, return 0): no stroke input, no line in it, a missing or malformed label
 * array, labels that are negative or not integers, strokes of a single label, stroke points
 * farther from the surface than MaximumProjectionDistance, surfaces refused by validation
 * (non-manifold, inconsistently oriented), NaN parameters.
 */
#ifndef vtkRegionGrowing_h
#define vtkRegionGrowing_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkRegionGrowing : public vtkPolyDataAlgorithm
{
public:
  static vtkRegionGrowing* New();
  vtkTypeMacro(vtkRegionGrowing, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// w, the metric's weight of the normal variation |n_p - n_q| (the mesh scaled into a unit
  /// box). Default 5.
  vtkSetClampMacro(NormalWeight, double, 0.0, 1e6);
  vtkGetMacro(NormalWeight, double);
  ///@}

  ///@{
  /// w*, the metric's weight of the curvature term f(k) per unit length. Default 5.
  vtkSetClampMacro(CurvatureWeight, double, 0.0, 1e6);
  vtkGetMacro(CurvatureWeight, double);
  ///@}

  ///@{
  /// How concave curvature k < 0 is augmented: 0 exponential (e^|k| - 1, the paper's), 1 linear
  /// (3 |k|), 2 square (k^2). Default 0.
  vtkSetClampMacro(CurvatureAugmentation, int, 0, 2);
  vtkGetMacro(CurvatureAugmentation, int);
  ///@}

  ///@{
  /// The curvature term per edge, as printed in the paper's discrete formula, instead of per unit
  /// length. Default off.
  vtkSetMacro(CurvaturePerEdge, bool);
  vtkGetMacro(CurvaturePerEdge, bool);
  vtkBooleanMacro(CurvaturePerEdge, bool);
  ///@}

  ///@{
  /// Stroke points farther from the surface than this fraction of the bounding-box diagonal are
  /// refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// The cell array of input 1 holding each stroke's label (named, not selected: see
  /// vtkHarmonicField). Default "Label".
  vtkSetStringMacro(StrokeLabelArrayName);
  vtkGetStringMacro(StrokeLabelArrayName);
  ///@}

  ///@{
  /// Name of the output point and cell arrays of labels. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

  /// The boundaries between labels (output 1).
  vtkPolyData* GetBoundary();

protected:
  vtkRegionGrowing();
  ~vtkRegionGrowing() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double NormalWeight = 5.0;
  double CurvatureWeight = 5.0;
  int CurvatureAugmentation = 0;
  bool CurvaturePerEdge = false;
  double MaximumProjectionDistance = 0.05;
  char* StrokeLabelArrayName = nullptr;
  char* SegmentArrayName = nullptr;

private:
  vtkRegionGrowing(const vtkRegionGrowing&) = delete;
  void operator=(const vtkRegionGrowing&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
