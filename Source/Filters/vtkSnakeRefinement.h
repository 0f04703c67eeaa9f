/**
 * @class vtkSnakeRefinement
 * @brief The boundaries of a segmented surface moved as snakes to where they are short, smooth and curved (Ji et al.
 * 2006, section 5.1).
 *
 * Input 0: a surface with a cell array of integer labels >= -1 (selected with
 * SetInputArrayToProcess(0, ...); default "Segment"): the output of vtkRegionGrowing, or of any
 * segmentation filter. Each boundary between two labels becomes a snake whose snaxels sit on the
 * edges it crosses; sweeps slide every snaxel along its edge to the position maximising
 * E_int * E_ext (the angle between its two segments in the tangent plane times |k_min| + |k_max|
 * plus SnakeCurvatureOffset), and vertex snaxels split onto the edges beyond them. Boundaries stay
 * inside triangles and cannot cross; points where three labels meet and the mesh's border stay
 * fixed. Input 1 (optional): override strokes, polylines drawn where the boundary should run
 * (section 5.2): after the refinement each replaces the part of the boundary within
 * OverrideRadius of it by itself. Without input 1 the override strokes are those drawn in the
 * panel (vtkDrawnStrokeAlgorithm; in ParaView: hold Ctrl and drag along where the boundary should
 * run), their labels unused.
 *
 * Output 0: the surface with the refined labels in the cell array of the input's name (a triangle
 * the snake crosses takes the label holding the larger part of its area), field data
 * "SnakeSweeps", "SnakeSlides" and "SnakeSplits". Output 1: the refined boundaries as polylines
 * with the cell arrays Length, Closed, LeftLabel and RightLabel (the smaller label on the left
 * seen from outside).
 *
 * Errors (vtkErrorMacro, return 0): a missing label array or labels that are not integers >= -1,
 * an override stroke of a single point, away from every boundary or farther from the surface than
 * MaximumProjectionDistance, surfaces refused by validation (non-manifold, inconsistently
 * oriented), NaN parameters.
 */
#ifndef vtkSnakeRefinement_h
#define vtkSnakeRefinement_h

#include "KerfFiltersModule.h"
#include "KerfSnakeParameters.h"
#include "vtkDrawnStrokeAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkSnakeRefinement : public vtkDrawnStrokeAlgorithm
{
public:
  static vtkSnakeRefinement* New();
  vtkTypeMacro(vtkSnakeRefinement, vtkDrawnStrokeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The snake and override parameters (KerfSnakeParameters.h); override strokes are input 1.
  kerfSnakeParametersMacro();

public:
  ///@{
  /// Override stroke points farther from the surface than this fraction of the bounding-box
  /// diagonal are refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  /// The refined boundaries (output 1).
  vtkPolyData* GetBoundary();

protected:
  vtkSnakeRefinement();
  ~vtkSnakeRefinement() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double MaximumProjectionDistance = 0.05;

private:
  vtkSnakeRefinement(const vtkSnakeRefinement&) = delete;
  void operator=(const vtkSnakeRefinement&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
