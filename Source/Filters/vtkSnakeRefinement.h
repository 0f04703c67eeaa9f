/**
 * @class vtkSnakeRefinement
 * @brief The boundaries of a segmented surface moved as snakes to where they are short, smooth and curved (Ji et al. 2006, section 5.1).
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
#include "vtkDrawnStrokeAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkSnakeRefinement : public vtkDrawnStrokeAlgorithm
{
public:
  static vtkSnakeRefinement* New();
  vtkTypeMacro(vtkSnakeRefinement, vtkDrawnStrokeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The most sweeps of the snake refinement; 0 leaves the snakes as they start (along mesh
  /// edges through the labelling's boundary vertices, a face whose three corners lie on the
  /// boundary taking the smaller label) for override strokes alone. Default 100.
  vtkSetClampMacro(SnakeIterations, int, 0, 100000);
  vtkGetMacro(SnakeIterations, int);
  ///@}

  ///@{
  /// The refinement ends after a sweep in which no snaxel moves farther than this fraction of the
  /// mean edge length. Default 0.01.
  vtkSetClampMacro(SnakeConvergence, double, 0.0, 1.0);
  vtkGetMacro(SnakeConvergence, double);
  ///@}

  ///@{
  /// Added to the snake's external energy |k_min| + |k_max| so that it straightens in flat
  /// regions too. Default 1.
  vtkSetClampMacro(SnakeCurvatureOffset, double, 0.0, 1e6);
  vtkGetMacro(SnakeCurvatureOffset, double);
  ///@}

  ///@{
  /// Positions a snaxel tries along its edge in a slide, both ends included. Default 8.
  vtkSetClampMacro(SnakeSlideSamples, int, 2, 1000);
  vtkGetMacro(SnakeSlideSamples, int);
  ///@}

  ///@{
  /// How far from an override stroke (input 1) the boundary is replaced by it, as a fraction of the
  /// bounding-box diagonal. Default 0.03.
  vtkSetClampMacro(OverrideRadius, double, 1e-6, 1.0);
  vtkGetMacro(OverrideRadius, double);
  ///@}

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
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int SnakeIterations = 100;
  double SnakeConvergence = 0.01;
  double SnakeCurvatureOffset = 1.0;
  int SnakeSlideSamples = 8;
  double OverrideRadius = 0.03;
  double MaximumProjectionDistance = 0.05;

private:
  vtkSnakeRefinement(const vtkSnakeRefinement&) = delete;
  void operator=(const vtkSnakeRefinement&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
