/**
 * @class vtkEasyMeshCut
 * @brief Easy Mesh Cut: a surface split into the parts that labelled strokes mark (Ji et al. 2006).
 *
 * Each stroke (a polyline of input 1, or a point of a vertex cell: a click) carries a label in the cell array named by
 * StrokeLabelArrayName: foreground 1 and background 0 cut out one part; more labels cut out more
 * parts. Without input 1, the strokes drawn in the panel (vtkDrawnStrokeAlgorithm, each with its
 * label), with the typed foreground and background points for the labels 1 and 0 where no stroke
 * of that label is drawn.
 * Fronts grow from the strokes under the improved isophotic metric (Ji et al. 2006, sections 3
 * and 4.2), a length that grows with the change of the normal and, strongly, with concave
 * curvature; where the boundaries go is BoundaryPlacement's choice (vtkStrokeGrowingAlgorithm):
 * by default random walks on the concavity-aware Laplacian, so parts end at concave creases,
 * then a minimum cut through the band where the walks hesitate (CutBand), or the paper's rule,
 * each vertex to its nearest stroke. With Refine, the
 * boundaries are then moved as snakes to where they are short, smooth and curved (section 5.1).
 * Override strokes (polylines of the optional input 2, else the drawn strokes of label -1) then
 * edit the boundary (section 5.2): each replaces the part of the boundary within OverrideRadius of
 * it by itself.
 *
 * Output 0: the surface with the cell array SegmentArrayName (the label of each triangle, -1 where
 * no stroke reaches: a component without strokes), the point array "IsophoticDistance" (the
 * metric distance to the nearest stroke, -1 where none reaches) and, with the random walks,
 * "Probability" (the probability of each point's grown label; where the cut gave a point its
 * second label, the larger of its two probabilities), and the field data "SegmentSizes" (the
 * faces of each label) and "SnakeSweeps". Output 1: the boundaries between
 * labels as polylines with the cell arrays Length, Closed, LeftLabel and RightLabel (the smaller
 * label on the left seen from outside).
 *
 * Errors (vtkErrorMacro, return 0): no strokes, no line in input 1, a missing or malformed label
 * array, labels that are negative or not integers, strokes of a single label (no background or no
 * foreground), stroke points farther from the surface than MaximumProjectionDistance, an
 * override stroke away from every boundary or of a single point, surfaces
 * refused by validation (non-manifold, inconsistently oriented), NaN parameters.
 */
#ifndef vtkEasyMeshCut_h
#define vtkEasyMeshCut_h

#include "KerfFiltersModule.h"
#include "KerfSnakeParameters.h"
#include "vtkStrokeGrowingAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkEasyMeshCut : public vtkStrokeGrowingAlgorithm
{
public:
  static vtkEasyMeshCut* New();
  vtkTypeMacro(vtkEasyMeshCut, vtkStrokeGrowingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Refine the grown boundaries as snakes (section 5.1). Default on.
  vtkSetMacro(Refine, bool);
  vtkGetMacro(Refine, bool);
  vtkBooleanMacro(Refine, bool);
  ///@}

  /// The snake and override parameters (KerfSnakeParameters.h); SnakeIterations 0 with Refine
  /// on leaves the grown boundaries for override strokes alone.
  kerfSnakeParametersMacro();

public:
  ///@{
  /// The typed strokes, used when input 1 is not connected for the labels without a drawn stroke
  /// (vtkDrawnStrokeAlgorithm): the foreground stroke (label 1) and the background stroke
  /// (label 0), each a polyline of one or more points (one point is a click), moved to the
  /// nearest surface points whatever their distance (in ParaView they start at the input's
  /// bounds).
  void SetNumberOfForegroundPoints(int count);
  int GetNumberOfForegroundPoints() const;
  void SetForegroundPoint(int index, double x, double y, double z);
  void SetNumberOfBackgroundPoints(int count);
  int GetNumberOfBackgroundPoints() const;
  void SetBackgroundPoint(int index, double x, double y, double z);
  ///@}

protected:
  vtkEasyMeshCut();
  ~vtkEasyMeshCut() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  bool Refine = true;

private:
  vtkEasyMeshCut(const vtkEasyMeshCut&) = delete;
  void operator=(const vtkEasyMeshCut&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
