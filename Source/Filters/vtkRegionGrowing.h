/**
 * @class vtkRegionGrowing
 * @brief Region growing from labelled strokes under the improved isophotic metric (Ji et al. 2006, section 4.2).
 *
 * The first half of Easy Mesh Cut, for pipelines that refine or inspect the grown parts on their
 * own (vtkRegionGrowing -> vtkSnakeRefinement gives what vtkEasyMeshCut gives in one step). Each
 * stroke (a polyline of input 1, or a point of a vertex cell: a click) carries a label in the cell array
 * named by StrokeLabelArrayName. The fronts grow from the strokes under the improved isophotic
 * metric (sections 3 and 4.2), a length that grows with the change of the normal and, strongly,
 * with concave curvature. By default (BoundaryPlacement random walks) each vertex then takes the
 * label a random walk from it on the concavity-aware Laplacian most likely reaches first, and each
 * triangle the label of largest probability summed over its corners; then a minimum cut through
 * the band where the walks hesitate between two labels (CutBand) moves the boundary onto the
 * short, concave way there (a moved vertex takes its second label, the triangles around it are
 * labelled again by their corners' two labels). With the paper's rule
 * (fronts) every vertex takes the label of its nearest stroke, a triangle the label two or three
 * of its corners share, and one whose three corners differ the label of the corner nearest to its
 * stroke.
 *
 * Output 0: the surface with the point and cell arrays SegmentArrayName (the label of each vertex
 * and triangle, -1 where no stroke reaches: a component without strokes), the point array
 * "IsophoticDistance" (the metric distance to the nearest stroke, -1 where none reaches) and, with
 * random walks, "Probability" (the probability of each point's label; where the cut gave a point
 * its second label, the larger of its two probabilities), field
 * data "UnreachableVertices" and "SegmentSizes" (the faces of each label). Output 1: the boundaries between labels
 * along mesh edges, as polylines with the cell arrays Length, Closed, LeftLabel and RightLabel (the smaller label on
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
#include "vtkStrokeGrowingAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkRegionGrowing : public vtkStrokeGrowingAlgorithm
{
public:
  static vtkRegionGrowing* New();
  vtkTypeMacro(vtkRegionGrowing, vtkStrokeGrowingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkRegionGrowing();
  ~vtkRegionGrowing() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

private:
  vtkRegionGrowing(const vtkRegionGrowing&) = delete;
  void operator=(const vtkRegionGrowing&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
