/**
 * @class vtkStrokeConstraintAlgorithm
 * @brief The strokes of the filters that place a harmonic cut's paired constraints along them
 * (vtkStrokeConstraints, vtkStrokeCut; SeamCut, section 2.1.1), and how they are sampled.
 * Abstract.
 *
 * Input 0: the surface. Input 1 (optional): the strokes, polylines near the surface (any number),
 * whose points are refused beyond MaximumProjectionDistance; without it the strokes are the
 * drawn strokes (vtkDrawnStrokeAlgorithm; in ParaView: hold Ctrl and drag over the surface) or,
 * when none is drawn, the typed stroke (SetStrokePoint), their points moved to the surface
 * whatever their distance. Between its points a stroke follows the surface (see
 * kerf::strokeConstraints). Each stroke
 * segment is resampled to SamplesPerSegment points; each sample, projected onto the surface, is
 * offset by +/- Offset along the surface, orthogonally to the stroke, and the two points get the
 * values IsoValue + 1 (left of the stroke, seen from outside) and IsoValue - 1.
 * kerf::ReadStrokeOptions reads these parameters.
 */
#ifndef vtkStrokeConstraintAlgorithm_h
#define vtkStrokeConstraintAlgorithm_h

#include "KerfFiltersModule.h"
#include "vtkDrawnStrokeAlgorithm.h"

#include <memory>

namespace kerf
{
class StrokePointList;
}

class KERFFILTERS_EXPORT vtkStrokeConstraintAlgorithm : public vtkDrawnStrokeAlgorithm
{
public:
  vtkTypeMacro(vtkStrokeConstraintAlgorithm, vtkDrawnStrokeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Samples per stroke segment (N_S). Default 4.
  vtkSetClampMacro(SamplesPerSegment, int, 1, 1000);
  vtkGetMacro(SamplesPerSegment, int);
  ///@}

  ///@{
  /// Offset eps_C of the constraint points from the stroke, as a fraction of the surface's
  /// bounding-box diagonal. Default 0.005 (half the paper's 0.01: measured closer to the
  /// user's intent on the benchmark, see Documentation/filters/HarmonicCuts.md).
  vtkSetClampMacro(Offset, double, 1e-6, 0.5);
  vtkGetMacro(Offset, double);
  ///@}

  ///@{
  /// A stroke's offset is at most this fraction of its length (0: no cap), so that the
  /// constraints of a short stroke (a loop round a small part) stay beside it. Default 0.05.
  vtkSetClampMacro(OffsetLengthFraction, double, 0.0, 1.0);
  vtkGetMacro(OffsetLengthFraction, double);
  ///@}

  ///@{
  /// The iso-value I of the cut: constraints are I + 1 and I - 1. Default 0. Must be finite and
  /// small enough that I +- 1 differ from I.
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /// Stroke points of input 1 farther from the surface than this fraction of its bounding-box
  /// diagonal are refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// The typed stroke's points (one stroke), used when input 1 is not connected and no stroke is
  /// drawn.
  void SetNumberOfStrokePoints(int count);
  int GetNumberOfStrokePoints() const;
  void SetStrokePoint(int index, double x, double y, double z);
  ///@}

  /// Connects strokes (optional second input: polylines).
  void SetStrokeConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkStrokeConstraintAlgorithm();
  ~vtkStrokeConstraintAlgorithm() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  int SamplesPerSegment = 4;
  double Offset = 0.005;
  double OffsetLengthFraction = 0.05;
  double IsoValue = 0.0;
  double MaximumProjectionDistance = 0.05;
  std::unique_ptr<kerf::StrokePointList> StrokePoints; ///< the panel's stroke

private:
  vtkStrokeConstraintAlgorithm(const vtkStrokeConstraintAlgorithm&) = delete;
  void operator=(const vtkStrokeConstraintAlgorithm&) = delete;
};

#endif
