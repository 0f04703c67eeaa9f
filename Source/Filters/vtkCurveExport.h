/**
 * @class vtkCurveExport
 * @brief Curve Export: cut curves on a surface turned into mesh edges by SeamCut's three export
 * operators, scissor, snap and inverse snap (SeamCut, section 4), and the charts they bound.
 *
 * Input 0: the surface. Input 1: the curves, polylines on the surface (isolines from Isoline
 * Cut or Stroke Cut, seams from Geodesic Seam); a polyline whose last point repeats its
 * first is closed. Each polyline is placed on the surface (kerf::PlaceLinesOnSurface): its
 * points are projected onto it, and consecutive points that share no triangle are joined across
 * the triangles between them.
 *
 * Modes: Scissor splits the triangles along the exact curves (new vertices at the curve points,
 * shared by the triangles of an edge; more triangles; the area is unchanged). Snap keeps the
 * mesh; each curve becomes the shortest edge path through the vertices nearest its points.
 * InverseSnap keeps the connectivity and moves the vertex nearest each curve point onto it
 * (the nearest point wins a vertex several points share; moves that would flip a triangle are
 * refused), then follows the edges as Snap does.
 *
 * Output 0: the exported surface with the cell array "Chart" (connected components of
 * triangles across edges that are not cut, numbered by their lowest triangle), the point array
 * "OriginalPointId" (the input point, -1 for a new scissor vertex), the input's point data
 * (interpolated at new vertices) and cell data (each triangle carries its input cell's), and the
 * field data ChartCount, MovedVertices, DroppedPoints and RefusedFlips. Output 1: the cut edges as
 * two-point lines whose point ids are output 0's (same points), for splitting the mesh open or
 * drawing the seams.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation, no curve on input 1, a curve
 * point farther from the surface than Tolerance mean edge lengths (naming the point), scissor
 * curves through zero-area triangles or non-manifold edges.
 */
#ifndef vtkCurveExport_h
#define vtkCurveExport_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkCurveExport : public vtkPolyDataAlgorithm
{
public:
  static vtkCurveExport* New();
  vtkTypeMacro(vtkCurveExport, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ExportMode
  {
    SCISSOR = 0,
    SNAP = 1,
    INVERSE_SNAP = 2
  };

  ///@{
  /// The export operator: SCISSOR (0), SNAP (1) or INVERSE_SNAP (2). Default SCISSOR.
  vtkSetClampMacro(Mode, int, SCISSOR, INVERSE_SNAP);
  vtkGetMacro(Mode, int);
  void SetModeToScissor() { this->SetMode(SCISSOR); }
  void SetModeToSnap() { this->SetMode(SNAP); }
  void SetModeToInverseSnap() { this->SetMode(INVERSE_SNAP); }
  ///@}

  ///@{
  /// How far a curve point may lie off the surface, in mean edge lengths of the surface; farther
  /// points are refused with their number in the message. Default 0.5.
  vtkSetClampMacro(Tolerance, double, 0.0, 1e6);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Cut the output open where charts meet: each point on a border between charts is copied once
  /// per chart around it (point data and OriginalPointId copied with it), so that the charts share
  /// no point and no edge, ready for texture coordinates or to be pulled apart; triangles and cell
  /// data are unchanged, and output 1 has each cut edge once per side. A curve that separates no
  /// charts (a seam ending inside one) stays closed. Default off.
  vtkSetMacro(SplitOpen, bool);
  vtkGetMacro(SplitOpen, bool);
  vtkBooleanMacro(SplitOpen, bool);
  ///@}

  /// The cut edges (output 1).
  vtkPolyData* GetCutEdges();

protected:
  vtkCurveExport();
  ~vtkCurveExport() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Mode = SCISSOR;
  double Tolerance = 0.5;
  bool SplitOpen = false;

private:
  vtkCurveExport(const vtkCurveExport&) = delete;
  void operator=(const vtkCurveExport&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
