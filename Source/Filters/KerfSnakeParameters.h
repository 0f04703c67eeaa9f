/**
 * The parameters of the snake refinement and of override strokes (Ji et al. 2006, sections 5.1
 * and 5.2), declared once for the filters that refine boundaries (vtkEasyMeshCut,
 * vtkSnakeRefinement) by kerfSnakeParametersMacro() in their class body:
 *
 * - SnakeIterations: the most sweeps of the snake refinement; 0 leaves the snakes as they start
 *   (along mesh edges through the labelling's boundary vertices, a face whose three corners lie
 *   on the boundary taking the smaller label), for override strokes alone. Default 100.
 * - SnakeConvergence: the refinement ends after a sweep in which no snaxel moves farther than
 *   this fraction of the mean edge length. Default 0.01.
 * - SnakeCurvatureOffset: added to the snake's external energy |k_min| + |k_max| so that it
 *   straightens in flat regions too. Default 1.
 * - SnakeSlideSamples: positions a snaxel tries along its edge in a slide, both ends included.
 *   Default 8.
 * - OverrideRadius: how far from an override stroke the boundary is replaced by it, as a fraction
 *   of the bounding-box diagonal. Default 0.03.
 *
 * The macro leaves the class body in its protected section.
 */
#ifndef KerfSnakeParameters_h
#define KerfSnakeParameters_h

#include "vtkSetGet.h"

// clang-format off
#define kerfSnakeParametersMacro()                                                                 \
public:                                                                                            \
  vtkSetClampMacro(SnakeIterations, int, 0, 100000);                                               \
  vtkGetMacro(SnakeIterations, int);                                                               \
  vtkSetClampMacro(SnakeConvergence, double, 0.0, 1.0);                                            \
  vtkGetMacro(SnakeConvergence, double);                                                           \
  vtkSetClampMacro(SnakeCurvatureOffset, double, 0.0, 1e6);                                        \
  vtkGetMacro(SnakeCurvatureOffset, double);                                                       \
  vtkSetClampMacro(SnakeSlideSamples, int, 2, 1000);                                               \
  vtkGetMacro(SnakeSlideSamples, int);                                                             \
  vtkSetClampMacro(OverrideRadius, double, 1e-6, 1.0);                                             \
  vtkGetMacro(OverrideRadius, double);                                                             \
                                                                                                   \
protected:                                                                                         \
  void PrintSnakeParameters(ostream& os, vtkIndent indent)                                         \
  {                                                                                                \
    os << indent << "SnakeIterations: " << this->SnakeIterations << "\n";                          \
    os << indent << "SnakeConvergence: " << this->SnakeConvergence << "\n";                        \
    os << indent << "SnakeCurvatureOffset: " << this->SnakeCurvatureOffset << "\n";                \
    os << indent << "SnakeSlideSamples: " << this->SnakeSlideSamples << "\n";                      \
    os << indent << "OverrideRadius: " << this->OverrideRadius << "\n";                            \
  }                                                                                                \
  int SnakeIterations = 100;                                                                       \
  double SnakeConvergence = 0.01;                                                                  \
  double SnakeCurvatureOffset = 1.0;                                                               \
  int SnakeSlideSamples = 8;                                                                       \
  double OverrideRadius = 0.03
// clang-format on

#endif
