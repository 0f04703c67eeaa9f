/**
 * @class vtkStrokeGrowingAlgorithm
 * @brief The labelled strokes and the improved isophotic metric of the filters that grow parts
 * from strokes (vtkRegionGrowing, vtkEasyMeshCut; Ji et al. 2006, sections 3 and 4.2). Abstract.
 *
 * Input 1 holds the strokes: polylines, or points of vertex cells (clicks), each with a label in
 * the cell array named by StrokeLabelArrayName; their points are moved to the nearest surface
 * points and refused beyond MaximumProjectionDistance. When input 1 is not connected, the strokes
 * are those drawn in the panel (vtkDrawnStrokeAlgorithm, each with its label; in ParaView: hold
 * Ctrl and drag over the surface, the label chosen in the panel or with the number keys), moved
 * to the nearest surface points; vtkEasyMeshCut adds its typed foreground and background points
 * for the labels 1 and 0 where no stroke of that label is drawn. Fronts grow from the strokes under the metric,
 * whose edge length grows with the change of the normal (NormalWeight) and, strongly, with
 * concave curvature (CurvatureWeight, CurvatureAugmentation).
 * BoundaryPlacement says where the boundaries between labels go: by default each vertex and
 * face takes the label that a random walk from it, on the concavity-aware Laplacian, most likely
 * reaches first (kerf::randomWalkLabels), so parts end at concave creases rather than halfway
 * between strokes, and a minimum cut through the band where the walks hesitate between two labels
 * (CutBand) puts the boundary on the shortest, most concave way there; or where the fronts meet (the paper's rule:
 * every vertex to the stroke nearest to it under the metric); or where the fronts meet moved by a minimum cut through
 * the band around them (CutBand; kerf::placeCuts). The labels are written as SegmentArrayName; output 1 holds the
 * boundaries between labels. kerf::ReadGrowingOptions reads the parameters.
 */
#ifndef vtkStrokeGrowingAlgorithm_h
#define vtkStrokeGrowingAlgorithm_h

#include "KerfFiltersModule.h"
#include "vtkDrawnStrokeAlgorithm.h"

class KERFFILTERS_EXPORT vtkStrokeGrowingAlgorithm : public vtkDrawnStrokeAlgorithm
{
public:
  vtkTypeMacro(vtkStrokeGrowingAlgorithm, vtkDrawnStrokeAlgorithm);
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
  /// length; parts leak into each other across oblique creases with it. Default off.
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

  /// Where the boundaries between labels go (BoundaryPlacement).
  enum BoundaryPlacements
  {
    /// Where the fronts meet under the metric (the paper's rule).
    BOUNDARY_FRONTS = 0,
    /// The fronts, moved by a minimum cut through the band where they meet (CutBand).
    BOUNDARY_MINIMUM_CUT = 1,
    /// Random walks from the strokes on the concavity-aware Laplacian, then a minimum cut
    /// through the band where they hesitate between two labels (CutBand).
    BOUNDARY_RANDOM_WALKS = 2
  };

  ///@{
  /// Where the boundaries between labels go: BOUNDARY_FRONTS, BOUNDARY_MINIMUM_CUT or
  /// BOUNDARY_RANDOM_WALKS. Default BOUNDARY_RANDOM_WALKS. With random walks the output gets a
  /// point array "Probability", the probability of each point's label (where the cut gave a point
  /// its second most probable label, the larger of its two probabilities).
  vtkSetClampMacro(BoundaryPlacement, int, BOUNDARY_FRONTS, BOUNDARY_RANDOM_WALKS);
  vtkGetMacro(BoundaryPlacement, int);
  void SetBoundaryPlacementToFronts() { this->SetBoundaryPlacement(BOUNDARY_FRONTS); }
  void SetBoundaryPlacementToMinimumCut() { this->SetBoundaryPlacement(BOUNDARY_MINIMUM_CUT); }
  void SetBoundaryPlacementToRandomWalks() { this->SetBoundaryPlacement(BOUNDARY_RANDOM_WALKS); }
  ///@}

  ///@{
  /// Cut placement (BOUNDARY_MINIMUM_CUT and BOUNDARY_RANDOM_WALKS): the band between two labels
  /// in which a minimum cut places their boundary, as the ratio of a vertex's distance to its
  /// nearest label over that to the second nearest. The distance is the metric's for the minimum
  /// cut (0 keeps the boundary where the fronts meet, the paper's rule) and 1 minus the label's
  /// probability for the random walks (0 keeps the walks' boundary). Default 0.3.
  vtkSetClampMacro(CutBand, double, 0.0, 0.99);
  vtkGetMacro(CutBand, double);
  ///@}

  ///@{
  /// The cell array of input 1 holding each stroke's label (named, not selected: see
  /// vtkHarmonicField). Default "Label".
  vtkSetStringMacro(StrokeLabelArrayName);
  vtkGetStringMacro(StrokeLabelArrayName);
  ///@}

  ///@{
  /// Name of the output arrays of labels (per cell; vtkRegionGrowing writes a point array of
  /// the same name too). Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

  /// The boundaries between labels (output 1).
  vtkPolyData* GetBoundary();

protected:
  vtkStrokeGrowingAlgorithm();
  ~vtkStrokeGrowingAlgorithm() override;

  /// Input 0 a surface, inputs 1 and up optional polydata (strokes), so that each filter decides
  /// what a missing one means (an error, the panel's strokes, no overrides).
  int FillInputPortInformation(int port, vtkInformation* info) override;

  double NormalWeight = 5.0;
  double CurvatureWeight = 5.0;
  int CurvatureAugmentation = 0;
  bool CurvaturePerEdge = false;
  double MaximumProjectionDistance = 0.05;
  int BoundaryPlacement = BOUNDARY_RANDOM_WALKS;
  double CutBand = 0.3;
  char* StrokeLabelArrayName = nullptr;
  char* SegmentArrayName = nullptr;

private:
  vtkStrokeGrowingAlgorithm(const vtkStrokeGrowingAlgorithm&) = delete;
  void operator=(const vtkStrokeGrowingAlgorithm&) = delete;
};

#endif
