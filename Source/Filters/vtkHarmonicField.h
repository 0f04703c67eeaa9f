/**
 * @class vtkHarmonicField
 * @brief A harmonic scalar field on a triangle surface from hard vertex values and soft point
 * constraints, with its per-face gradient.
 *
 * Constraints, in any combination:
 * - hard (Dirichlet) values on vertices, with UseHardValues on: the surface's point array
 *   selected as input array 0 (SetInputArrayToProcess(0, 0, 0,
 *   vtkDataObject::FIELD_ASSOCIATION_POINTS, name); default "HardValue"), whose non-NaN entries are
 *   fixed values (NaN marks a free vertex);
 * - points on the second input (any vtkPointSet, for example vtkStrokeConstraints' output) with
 *   the point array named ConstraintValueArrayName (default "ConstraintValue"; a name rather than
 *   an input array index because ParaView 5.11's pipeline aborts on input arrays selected on a
 *   second input port while the first has its own, see Documentation/architecture.md). Each point is
 *   projected onto the surface; its nearest face and barycentric coordinates make a soft
 *   least-squares constraint of weight SoftConstraintWeight (SeamCut, Eq. 1), or, with
 *   HardConstraints on, a hard value at the nearest vertex.
 * With hard values only the field is harmonic (L_FF f = -L_FD f_D, ROI Scissor, Eq. 1); with
 * soft constraints it minimises ||L f||^2 + w^2 sum (C_i f - c_i)^2 (see kerf::HarmonicFieldSolver).
 *
 * The Laplacian's weights are chosen with Weighting: uniform, cotangent (default), the
 * concavity-aware weights of Au et al. 2011 (as ROI Scissor, Eq. 2-3), ROI Scissor's smooth
 * concavity weights (section 3.1), or the cotangent weights of the intrinsic Delaunay
 * triangulation (Bobenko and Springborn 2007: nonnegative, and linearly precise on planar meshes
 * however obtuse their triangles), solved on the intrinsic triangulation's edges over the same
 * vertices while constraints and the output stay on the input's triangles.
 *
 * The sparse Cholesky factorization (CHOLMOD; Eigen's SimplicialLDLT without it) is kept between
 * executions: while the surface, the weights and the constraint locations stay the same, a new
 * execution only back-substitutes (new values); new soft-constraint locations update the cached
 * factorization instead of computing a new one. The output's field data says which happened
 * ("SolverWork") and the relative residual of the solve ("RelativeResidual").
 *
 * Output: the surface with point array HarmonicField and cell arrays FieldGradient (3
 * components) and FieldGradientMagnitude (names are parameters). Points used by no triangle get
 * the value 0. Beside the field, HarmonicFieldClamped (the field's name + "Clamped"): the field
 * clamped to the range of the constraint values, the active scalars, so that a colour map over
 * its range shows the two sides and the transition where cuts lie (a least-squares field
 * overshoots its constraints far from them). It is for display; cut with the field itself.
 *
 * Errors (vtkErrorMacro, return 0, no NaN output): a connected component without any constraint,
 * no constraint at all, constraint points farther from the surface than
 * MaximumProjectionDistance, NaN constraint values, a vertex given two different hard values, a
 * failed factorization, and surfaces refused by validation (NaN coordinates, non-manifold or
 * inconsistently oriented surfaces, triangles repeating a point, duplicate triangles).
 */
#ifndef vtkHarmonicField_h
#define vtkHarmonicField_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkHarmonicField : public vtkPolyDataAlgorithm
{
public:
  static vtkHarmonicField* New();
  vtkTypeMacro(vtkHarmonicField, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Weightings
  {
    UNIFORM = 0,
    COTANGENT = 1,
    CONCAVITY_AWARE = 2,
    SMOOTH_CONCAVITY = 3,
    INTRINSIC_DELAUNAY = 4
  };

  ///@{
  /// The Laplacian's edge weights. Default COTANGENT.
  vtkSetClampMacro(Weighting, int, UNIFORM, INTRINSIC_DELAUNAY);
  vtkGetMacro(Weighting, int);
  void SetWeightingToUniform() { this->SetWeighting(UNIFORM); }
  void SetWeightingToCotangent() { this->SetWeighting(COTANGENT); }
  void SetWeightingToConcavityAware() { this->SetWeighting(CONCAVITY_AWARE); }
  void SetWeightingToSmoothConcavity() { this->SetWeighting(SMOOTH_CONCAVITY); }
  void SetWeightingToIntrinsicDelaunay() { this->SetWeighting(INTRINSIC_DELAUNAY); }
  ///@}

  enum Formulations
  {
    POINT_VALUES = 0,
    LEAST_SQUARES = 1,
    AUTOMATIC = 2
  };

  ///@{
  /// How the soft constraints shape the field. LEAST_SQUARES: SeamCut's least squares, the
  /// squared Laplacian factored, the cut that follows the user's strokes most closely.
  /// POINT_VALUES: the field harmonic away from the constraint points and equal to their values
  /// there; the plain Laplacian factored, about three times faster on a fresh mesh. AUTOMATIC
  /// (default): least squares on coarse meshes, point values where the mean edge is at most 1/180
  /// of the bounding-box diagonal (the default stroke offset spans 0.9 edges or more), where the
  /// two cuts agree to a fraction of the stroke offset and the first cut is much cheaper
  /// (kerf::automaticFormulation; figures in Documentation/filters/HarmonicCuts.md).
  vtkSetClampMacro(Formulation, int, POINT_VALUES, AUTOMATIC);
  vtkGetMacro(Formulation, int);
  ///@}

  ///@{
  /// beta on edges touching a concave vertex (CONCAVITY_AWARE). Default 0.01 (Au et al.).
  vtkSetClampMacro(ConcaveBeta, double, 1e-6, 1.0);
  vtkGetMacro(ConcaveBeta, double);
  ///@}

  ///@{
  /// H_max of SMOOTH_CONCAVITY as a quantile of the concave mean curvature; 1 (default, the
  /// paper) is the maximum, slightly less ignores a few noisy vertices.
  vtkSetClampMacro(ConcavityQuantile, double, 0.5, 1.0);
  vtkGetMacro(ConcavityQuantile, double);
  ///@}

  ///@{
  /// Weight w of the soft constraints, relative to the mean diagonal of the Laplacian (so that
  /// it does not depend on the mesh's scale or the weighting). Default 1.
  vtkSetClampMacro(SoftConstraintWeight, double, 1e-6, 1e6);
  vtkGetMacro(SoftConstraintWeight, double);
  ///@}

  ///@{
  /// If on, the second input's points fix the value of their nearest vertex instead of being
  /// soft constraints. Default off.
  vtkSetMacro(HardConstraints, bool);
  vtkGetMacro(HardConstraints, bool);
  vtkBooleanMacro(HardConstraints, bool);
  ///@}

  ///@{
  /// Constraint points farther from the surface than this fraction of its bounding-box diagonal
  /// are refused; 0 means no limit. Default 0.02.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// Whether the hard values (input array 0, a point array of the surface; NaN: free vertex)
  /// are used; off ignores them, so an array can stay selected. Default off.
  vtkSetMacro(UseHardValues, bool);
  vtkGetMacro(UseHardValues, bool);
  vtkBooleanMacro(UseHardValues, bool);
  ///@}

  ///@{
  /// Name of the point array of the constraint points (second input) holding their values.
  /// Default "ConstraintValue".
  vtkSetStringMacro(ConstraintValueArrayName);
  vtkGetStringMacro(ConstraintValueArrayName);
  ///@}

  ///@{
  /// Output array names. Defaults "HarmonicField", "FieldGradient", "FieldGradientMagnitude".
  vtkSetStringMacro(FieldArrayName);
  vtkGetStringMacro(FieldArrayName);
  vtkSetStringMacro(GradientArrayName);
  vtkGetStringMacro(GradientArrayName);
  vtkSetStringMacro(GradientMagnitudeArrayName);
  vtkGetStringMacro(GradientMagnitudeArrayName);
  ///@}

  /// Connects the constraint points (optional second input).
  void SetConstraintConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkHarmonicField();
  ~vtkHarmonicField() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Weighting = COTANGENT;
  int Formulation = AUTOMATIC;
  double ConcaveBeta = 0.01;
  double ConcavityQuantile = 1.0;
  double SoftConstraintWeight = 1.0;
  bool HardConstraints = false;
  double MaximumProjectionDistance = 0.02;
  bool UseHardValues = false;
  char* ConstraintValueArrayName = nullptr;
  char* FieldArrayName = nullptr;
  char* GradientArrayName = nullptr;
  char* GradientMagnitudeArrayName = nullptr;

private:
  vtkHarmonicField(const vtkHarmonicField&) = delete;
  void operator=(const vtkHarmonicField&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
