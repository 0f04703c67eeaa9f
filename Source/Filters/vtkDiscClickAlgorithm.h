/**
 * @class vtkDiscClickAlgorithm
 * @brief The clicks and radii of the filters that place geodesic discs on a surface
 * (vtkGeodesicDisc, vtkROIScissor; ROI Scissor, sections 4.1 and 5.2). Abstract.
 *
 * Input 0: the surface. Input 1 (optional): clicks, a vtkPointSet whose points each add a
 * geodesic disc, each moved to the nearest surface point and refused beyond
 * MaximumProjectionDistance; without it the clicks are the discs drawn in the panel (DrawnDiscs:
 * in ParaView, hold Ctrl, press on the surface and drag outward to set the radius; Shift too to
 * subtract the disc) or, when none is drawn, the typed click ClickPoint; both are moved to the
 * nearest surface point whatever their distance (the typed click starts at the input's bounds). A click's point
 * data may give its own radius (the array ClickRadiusArrayName, default "Radius", a fraction of
 * the diagonal like Radius) and make it subtract its disc instead of adding it (the array
 * ClickSubtractArrayName, default "Subtract": non-zero subtracts); without these arrays every
 * click adds a disc of radius Radius. kerf::ReadDiscClicks reads them.
 */
#ifndef vtkDiscClickAlgorithm_h
#define vtkDiscClickAlgorithm_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

namespace kerf
{
class DrawnDiscList;
}

class KERFFILTERS_EXPORT vtkDiscClickAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkDiscClickAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The discs drawn in the panel, each a click (x, y, z), its geodesic radius in the input's
  /// units and whether it subtracts its disc (non-zero) from the union of the others. When any
  /// is drawn they replace the typed click (ClickPoint with Radius or AbsoluteRadius). Default:
  /// none.
  void SetNumberOfDrawnDiscs(int count);
  int GetNumberOfDrawnDiscs() const;
  void SetDrawnDisc(int index, double x, double y, double z, double radius, double subtract);
  void AddDrawnDisc(double x, double y, double z, double radius, bool subtract);
  void RemoveAllDrawnDiscs();
  ///@}

  ///@{
  /// The typed click, used when input 1 is not connected and no disc is drawn, moved to the
  /// nearest surface point whatever its distance (in ParaView it starts at the input's bounds).
  /// Default (0, 0, 0).
  vtkSetVector3Macro(ClickPoint, double);
  vtkGetVector3Macro(ClickPoint, double);
  ///@}

  ///@{
  /// Geodesic radius r of each click's disc, as a fraction of the bounding-box diagonal. Default 0.25.
  vtkSetClampMacro(Radius, double, 1e-6, 10.0);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Geodesic radius of each click's disc in the input's units; when positive it replaces Radius
  /// (clicks' own radii stay fractions of the diagonal). ParaView sets it with the sphere widget
  /// centred on the click. Default 0 (Radius is used).
  vtkSetClampMacro(AbsoluteRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AbsoluteRadius, double);
  ///@}

  ///@{
  /// Clicks of input 1 farther from the surface than this fraction of the bounding-box diagonal are
  /// refused; 0 means no limit. Default 0.05.
  vtkSetClampMacro(MaximumProjectionDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumProjectionDistance, double);
  ///@}

  ///@{
  /// Point arrays of input 1 read when present: each click's radius (fraction of the diagonal;
  /// default name "Radius") and whether it subtracts its disc (non-zero; default name "Subtract").
  vtkSetStringMacro(ClickRadiusArrayName);
  vtkGetStringMacro(ClickRadiusArrayName);
  vtkSetStringMacro(ClickSubtractArrayName);
  vtkGetStringMacro(ClickSubtractArrayName);
  ///@}

protected:
  vtkDiscClickAlgorithm();
  ~vtkDiscClickAlgorithm() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  double ClickPoint[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.25;
  double AbsoluteRadius = 0.0;
  double MaximumProjectionDistance = 0.05;
  char* ClickRadiusArrayName = nullptr;
  char* ClickSubtractArrayName = nullptr;
  std::unique_ptr<kerf::DrawnDiscList> DrawnDiscs;

private:
  vtkDiscClickAlgorithm(const vtkDiscClickAlgorithm&) = delete;
  void operator=(const vtkDiscClickAlgorithm&) = delete;
};

#endif
