/**
 * @class vtkStrokeConstraints
 * @brief Turns strokes drawn on a surface into the paired constraints of a harmonic cut
 * (SeamCut, section 2.1.1).
 *
 * Each stroke is a polyline near the surface: the lines of the second input (any number of
 * strokes), or, when no second input is connected, the points set with SetStrokePoint (one
 * stroke; ParaView shows them as an interactive polyline). Each stroke segment is resampled to
 * SamplesPerSegment points (N_S; default 4 as in the paper); each sample is projected onto the
 * surface and offset by +/- Offset (eps_C, a fraction of the bounding-box diagonal, default
 * 0.005, half the paper's 0.01) along the direction tangent to the surface and orthogonal to the
 * stroke; both points are projected again and get the values IsoValue + 1 (left of the stroke,
 * seen from outside) and IsoValue - 1. IsoValue is 0 for a new cut; to refine a cut at iso-value
 * I, set it to I (SeamCut, section 3).
 *
 * Output: a vtkPolyData of vertices at the constraint points with the point arrays
 * "ConstraintValue" (the value) and "Side" (+1 or -1), ready for vtkHarmonicField's second
 * input, and the field data "IsoValue".
 *
 * Errors: no stroke, a stroke with fewer than two distinct points, stroke points farther from the
 * surface than MaximumProjectionDistance (a fraction of the diagonal, default 0.05), and
 * surfaces refused by validation.
 */
#ifndef vtkStrokeConstraints_h
#define vtkStrokeConstraints_h

#include "KerfFiltersModule.h"
#include "vtkStrokeConstraintAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkStrokeConstraints : public vtkStrokeConstraintAlgorithm
{
public:
  static vtkStrokeConstraints* New();
  vtkTypeMacro(vtkStrokeConstraints, vtkStrokeConstraintAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkStrokeConstraints();
  ~vtkStrokeConstraints() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

private:
  vtkStrokeConstraints(const vtkStrokeConstraints&) = delete;
  void operator=(const vtkStrokeConstraints&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
