/**
 * @class vtkGeodesicDisc
 * @brief The geodesic discs around clicks, united or subtracted: ROI Scissor's candidate region
 * C(r) on its own (ROI Scissor, section 4.1).
 *
 * Input 0: the surface. Input 1 (optional): the clicks, each adding a geodesic disc or, with a
 * non-zero value in the point array ClickSubtractArrayName, subtracting it (ROI Scissor, section
 * 5.2), each with the radius Radius or its own; without input 1, ClickPoint. The clicks' parameters and the rules that
 * place them on the surface are vtkDiscClickAlgorithm's.
 *
 * The disc of a click s is C(r) = {i | d_g(i, s) < r} with d_g by the heat method (the
 * factorization cached on the surface); the region is the union of the added discs minus the
 * subtracted ones, the region vtkROIScissor solves its field on. Each click's distance is kept:
 * a new radius or a new click beside earlier ones computes only the new click's distance.
 *
 * Output: the surface with the point array "GeodesicDisc" (1 inside, 0 outside; the name is a
 * parameter, its active scalars), the cell array of the same name (the same rule at each face's
 * centroid, its distances averaged), the point array "ClickDistance" (the geodesic distance to
 * the nearest adding click; +infinity off its component) and the field data SegmentSizes (the faces outside and
 * inside), RegionArea, RegionAreaFraction (of the whole surface) and ClickDistanceFields (the distance fields this
 * filter has computed for its clicks on this surface, kept ones not counted again).
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, a click of input 1 farther
 * from the surface than MaximumProjectionDistance, clicks on several components, a radius that is
 * not positive, discs holding no vertex (a radius below the distance to the nearest vertex, or
 * every adding click inside a subtracted disc), discs covering their whole component (a radius
 * larger than the mesh), NaN parameters.
 */
#ifndef vtkGeodesicDisc_h
#define vtkGeodesicDisc_h

#include "KerfFiltersModule.h"
#include "vtkDiscClickAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkGeodesicDisc : public vtkDiscClickAlgorithm
{
public:
  static vtkGeodesicDisc* New();
  vtkTypeMacro(vtkGeodesicDisc, vtkDiscClickAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Name of the output point and cell arrays of the region. Default "GeodesicDisc".
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// Name of the output point array of the distance to the nearest adding click. Default
  /// "ClickDistance".
  vtkSetStringMacro(DistanceArrayName);
  vtkGetStringMacro(DistanceArrayName);
  ///@}

protected:
  vtkGeodesicDisc();
  ~vtkGeodesicDisc() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  char* RegionArrayName = nullptr;
  char* DistanceArrayName = nullptr;

private:
  vtkGeodesicDisc(const vtkGeodesicDisc&) = delete;
  void operator=(const vtkGeodesicDisc&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
