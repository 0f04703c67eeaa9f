/**
 * @class vtkStrokeCut
 * @brief Stroke Cut: a mesh cut along a stroke in one filter (SeamCut, section 2.1): the
 * stroke's constraints, the harmonic field, the isoline nearest the stroke and the segments it
 * bounds.
 *
 * The common case of the three-filter pipeline vtkStrokeConstraints -> vtkHarmonicField ->
 * vtkIsolineCut (which stays available for every other case), with the same Core
 * (kerf::HarmonicCutSession) and the same results. The strokes are the polylines of input 1 or,
 * without it, the strokes drawn in the panel (vtkDrawnStrokeAlgorithm; in ParaView: hold Ctrl and
 * drag across the surface) or, when none is drawn, the typed stroke (SetStrokePoint). A new
 * stroke re-solves with the kept factorization (an update); changing IsoValue only re-extracts
 * the cut.
 *
 * Output 0: the surface with the point arrays "HarmonicField" and "HarmonicFieldClamped" (for
 * display, see vtkHarmonicField), the cell array "Segment" (the two sides of the cut, split
 * further into connected components; the active scalars, what ParaView colours by) and the
 * field data "SolverWork", "RelativeResidual" and "SegmentSizes" (the faces of each segment). Output 1: the cut as
 * polylines (IsoValue, Score, Length, Closed).
 *
 * On a surface of several connected components, the strokes cut the components they touch; the
 * others stay whole (each one segment), as if on the strokes' +1 side.
 *
 * Errors (vtkErrorMacro, return 0): no stroke, a stroke with fewer than two distinct points or
 * farther from the surface than MaximumProjectionDistance, surfaces refused by validation (the
 * field needs an edge-manifold, consistently oriented surface), NaN parameters.
 */
#ifndef vtkStrokeCut_h
#define vtkStrokeCut_h

#include "KerfFiltersModule.h"
#include "vtkStrokeConstraintAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkStrokeCut : public vtkStrokeConstraintAlgorithm
{
public:
  static vtkStrokeCut* New();
  vtkTypeMacro(vtkStrokeCut, vtkStrokeConstraintAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The Laplacian's weights, as vtkHarmonicField's Weighting. Default 1 (cotangent).
  vtkSetClampMacro(Weighting, int, 0, 3);
  vtkGetMacro(Weighting, int);
  ///@}

  ///@{
  /// How the stroke's constraints shape the field, as vtkHarmonicField's Formulation: 0 point
  /// values (faster), 1 least squares (the most faithful cut), 2 automatic (default: least
  /// squares on coarse meshes, point values where the mean edge is at most 1/180 of the diagonal).
  vtkSetClampMacro(Formulation, int, 0, 2);
  vtkGetMacro(Formulation, int);
  ///@}

  ///@{
  /// Weight of the stroke's soft constraints, relative to the Laplacian's mean diagonal. Default 1.
  vtkSetClampMacro(SoftConstraintWeight, double, 1e-6, 1e6);
  vtkGetMacro(SoftConstraintWeight, double);
  ///@}

  /// The cut polylines (output 1).
  vtkPolyData* GetCut();

protected:
  vtkStrokeCut();
  ~vtkStrokeCut() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Weighting = 1;
  int Formulation = 2;
  double SoftConstraintWeight = 1.0;

private:
  vtkStrokeCut(const vtkStrokeCut&) = delete;
  void operator=(const vtkStrokeCut&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
