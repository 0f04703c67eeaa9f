/**
 * @class vtkChartParameterization
 * @brief Texture coordinates for a surface cut into charts: each chart flattened by least-squares
 * conformal maps (Levy et al. 2002) or linear angle based flattening (LinABF, Zayer, Levy and
 * Seidel 2007) and packed into the unit square.
 *
 * Input: a triangle surface (polygons are triangulated) with a per-cell label array, selected with
 * SetInputArrayToProcess (default the cell array "Chart"; "Segment" of the segmentation filters
 * works as well). Each connected piece of a label is a chart. A chart that is not a topological
 * disk (closed, with several boundary loops, or with handles) is cut into one when CutToDisks is
 * on (the default; kerf::cutToDisk: handles cut along short loops, boundary loops joined by
 * shortest paths, a closed sphere-like chart opened along the shortest path between two
 * vertices far apart); with it off such charts are refused. Method chooses how each chart is
 * flattened: LSCM (the default, the faster) or LINABF (angles first, then positions; less
 * distortion where a chart is strongly curved, about twice the time).
 *
 * Output 0: the surface cut open along the chart borders (a point is duplicated for each chart
 * that uses it), with the point arrays TextureCoordinatesName (default "UV", the texture
 * coordinates, set as TCoords) and "OriginalPointId", the cell arrays "Chart" (the label),
 * "Stretch" (sqrt((s1^2 + s2^2) / 2), Sander et al. 2001), "Shear" (s1 / s2) and "Flipped" (1
 * where the texture image is mirrored), s1 >= s2 the singular values of the map from the triangle
 * to its texture image after each chart is scaled to its 3D area; the input's point and cell
 * arrays are kept (copied to the duplicated points). Field data: MeanStretch, MaxStretch,
 * MeanShear, MaxShear (area-weighted means), L2Stretch (Sander et al. 2001's L2 norm of the
 * inverse map, 1 only for an isometry), FlippedFaces, OverlappingChartPairs, ChartCount,
 * TexelScale, CutCharts (charts cut into disks), and per chart (in increasing label order)
 * ChartLabel, ChartMeanStretch, ChartL2Stretch, ChartMaxStretch, ChartMeanShear, ChartMaxShear,
 * ChartFlippedFaces, ChartCutEdges and ChartCutLength (the cut that made it a disk; 0 for a disk),
 * ChartSeams and ChartSeamLength (the seams added, MaximumSeams).
 *
 * Output 1: the same triangles at their texture coordinates in the plane z = 0, with the cell
 * arrays of output 0: the layout, for display beside the surface.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation (non-manifold, inconsistently
 * oriented, zero-area triangles, NaN coordinates), a missing or non-integer label array, and
 * charts that are not disks when CutToDisks is off (every such chart named by its label, with its
 * boundary loops and genus). Nothing is flattened with overlaps.
 */
#ifndef vtkChartParameterization_h
#define vtkChartParameterization_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkChartParameterization : public vtkPolyDataAlgorithm
{
public:
  static vtkChartParameterization* New();
  vtkTypeMacro(vtkChartParameterization, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FlatteningMethod
  {
    LSCM = 0,
    LINABF = 1
  };

  ///@{
  /// How each chart is flattened: LSCM (0), least-squares conformal maps, or LINABF (1), linear
  /// angle based flattening (kerf::linearAngleBasedFlattening). Default LSCM, the faster (timings
  /// and distortion in Documentation/filters/ChartParameterization.md).
  vtkSetClampMacro(Method, int, LSCM, LINABF);
  vtkGetMacro(Method, int);
  void SetMethodToLSCM() { this->SetMethod(LSCM); }
  void SetMethodToLinABF() { this->SetMethod(LINABF); }
  ///@}

  ///@{
  /// Gap between charts, and between a chart and the border of the unit square, as a fraction of
  /// the square's side, in [0, 0.25]. Default 0.01.
  vtkSetClampMacro(Margin, double, 0.0, 0.25);
  vtkGetMacro(Margin, double);
  ///@}

  ///@{
  /// Cut charts that are not disks into disks (kerf::cutToDisk) instead of refusing them.
  /// Default on.
  vtkSetMacro(CutToDisks, bool);
  vtkGetMacro(CutToDisks, bool);
  vtkBooleanMacro(CutToDisks, bool);
  ///@}

  ///@{
  /// At most this many seams added to each chart where its map is worst, until its L2 stretch
  /// is at most SeamStretchTarget (cut augmentation, Gu, Gortler and Hoppe 2002; see
  /// kerf::ChartParameterizationOptions::maximumSeams): a chart with protrusions (legs, ears) gets
  /// a seam from each tip to its border. Default 10; 0 for none; at most 1000.
  vtkSetClampMacro(MaximumSeams, int, 0, 1000);
  vtkGetMacro(MaximumSeams, int);
  ///@}

  ///@{
  /// The L2 stretch at which no more seams are added, at least 1. Default 1.2.
  vtkSetClampMacro(SeamStretchTarget, double, 1.0, 1e6);
  vtkGetMacro(SeamStretchTarget, double);
  ///@}

  ///@{
  /// Name of the output texture-coordinate array. Default "UV".
  vtkSetStringMacro(TextureCoordinatesName);
  vtkGetStringMacro(TextureCoordinatesName);
  ///@}

protected:
  vtkChartParameterization();
  ~vtkChartParameterization() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Method = LSCM;
  double Margin = 0.01;
  bool CutToDisks = true;
  int MaximumSeams = 10;
  double SeamStretchTarget = 1.2;
  char* TextureCoordinatesName = nullptr;

private:
  vtkChartParameterization(const vtkChartParameterization&) = delete;
  void operator=(const vtkChartParameterization&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
