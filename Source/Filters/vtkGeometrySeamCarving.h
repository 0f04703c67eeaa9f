/**
 * @class vtkGeometrySeamCarving
 * @brief Geometry Seam Carving: moves a handle region of a surface and deforms the modeling
 * region between it and the fixed region, splitting or collapsing precomputed ring seams where the
 * deformation stretches or squashes it, so that features keep their shape (Dekkers and Kobbelt
 * 2014, section 3.3).
 *
 * Input: the output of vtkGeometrySeams: a triangle surface with the point array "Region"
 * (0 fixed, 1 modeling, 2 handle) and the cell arrays "RingSeam", "Sector" and "EdgeCost",
 * selected with SetInputArrayToProcess indices 0, 1, 2 and 3.
 *
 * HandleTransform: a linear transform (vtkTransform; in ParaView the Transform widget) applied to
 * the handle points; none is the identity. The filter keeps its editing session between runs
 * while the input and the options are unchanged: each run starts from the seam state the
 * previous run left (the paper's interaction), and returning the transform to the identity
 * undoes every split and collapse and gives back the input's points and triangles.
 *
 * Output: the deformed surface, re-meshed where seams were executed, with the point arrays
 * "OriginalPointId" (input point, -1 for points splits made) and the region array (new points
 * are modeling points), the cell arrays "RingSeam" and "Sector" (triangles made by a split keep
 * their ring and sector), and the field data SectorState (per sector: +k rings split, -k
 * collapsed), SplitSegments, CollapsedSegments and SkippedOperations. The input's other arrays
 * are not carried (the triangles change).
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, polygons or repeated points
 * (run Triangulate and Clean first), missing arrays (run Geometry Seams first), region layouts
 * that are not a ring, a transform that is singular or not finite, and a stiffness that is NaN,
 * negative or (epsilon) zero.
 */
#ifndef vtkGeometrySeamCarving_h
#define vtkGeometrySeamCarving_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class vtkLinearTransform;

class KERFFILTERS_EXPORT vtkGeometrySeamCarving : public vtkPolyDataAlgorithm
{
public:
  static vtkGeometrySeamCarving* New();
  vtkTypeMacro(vtkGeometrySeamCarving, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The handle's transform; nullptr (the default) is the identity.
  void SetHandleTransform(vtkLinearTransform* transform);
  vtkLinearTransform* GetHandleTransform();
  ///@}

  ///@{
  /// s of Eq. 7: stiffness(v) = s ang(v) + epsilon, with ang(v) the normal-cone angle; feature
  /// points take less of the deformation. Default 10 (the paper's octopus and seahorse).
  vtkSetMacro(StiffnessScale, double);
  vtkGetMacro(StiffnessScale, double);
  ///@}

  ///@{
  /// epsilon of Eq. 7, which keeps flat points' springs positive. Default 0.1.
  vtkSetMacro(StiffnessEpsilon, double);
  vtkGetMacro(StiffnessEpsilon, double);
  ///@}

  ///@{
  /// Execute ring seams (the plastic deformation). Off gives the elastic result alone (weighted
  /// Laplace editing), for comparison. Default on.
  vtkSetMacro(Plastic, bool);
  vtkGetMacro(Plastic, bool);
  vtkBooleanMacro(Plastic, bool);
  ///@}

  ///@{
  /// A ring segment is not split or collapsed in its sector when one of its triangles has a
  /// corner whose normal-cone angle, scaled to [0, 1] over the modeling region, exceeds this: a
  /// ring that cannot go around a feature leaves it alone there. In [0, 1]; 1 executes every
  /// segment. Default 0.5.
  vtkSetClampMacro(SalientThreshold, double, 0.0, 1.0);
  vtkGetMacro(SalientThreshold, double);
  ///@}

  /// Includes the transform's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkGeometrySeamCarving();
  ~vtkGeometrySeamCarving() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  double StiffnessScale = 10.0;
  double StiffnessEpsilon = 0.1;
  bool Plastic = true;
  double SalientThreshold = 0.5;

private:
  vtkGeometrySeamCarving(const vtkGeometrySeamCarving&) = delete;
  void operator=(const vtkGeometrySeamCarving&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
