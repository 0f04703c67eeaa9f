/**
 * @class vtkGeometrySeams
 * @brief Geometry Seams: the preprocessing of geometry seam carving (Dekkers and Kobbelt 2014,
 * section 3.2) — low-saliency ring seams of a modeling region that an editing filter splits or
 * collapses when the region between a handle and the fixed part is stretched or squashed.
 *
 * Input: a triangle surface with a per-point region array (selected with
 * SetInputArrayToProcess(0, ...), default "Region"): 0 fixed, 1 modeling, 2 handle. The
 * triangles with a modeling point must form a ring (an annulus) between the handle and the fixed
 * region, as around a leg or a handle of a model.
 *
 * Output 0: the surface with the point arrays "HarmonicField" (H, uniform Laplacian, 0 on the
 * handle, 1 on the fixed region, Eq. 1-2) and "Sector" (the sector between two sector contours,
 * -1 off the modeling points), and the cell arrays "RingSeam" (index of the ring seam a triangle
 * belongs to, cheapest ring 0, -1 elsewhere) and "EdgeCost" (the mean over a triangle's three
 * edges of kappa(e) / (Alpha + Beta + Gamma), Eq. 3, in [0, 1]; -1 off the modeling region).
 * Field data RingCount (rings found; fewer than NumberOfRings when no more fit).
 * Output 1: the iso-contours H = j / NumberOfIsoContours (j = 0 and the last are the region's
 * boundaries) and the sector contours, as polylines with the cell arrays Kind (0 iso, 1 sector),
 * ContourIndex (j, or the sector contour's index), Length and Closed.
 *
 * Errors (vtkErrorMacro, return 0): surfaces refused by validation (non-manifold, inconsistent
 * orientation, NaN coordinates), a missing or malformed region array, region layouts that are
 * not a ring (no handle, no fixed region, handle next to fixed, several parts, a modeling region
 * reaching the border), counts below 1 and negative or NaN weights.
 */
#ifndef vtkGeometrySeams_h
#define vtkGeometrySeams_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkGeometrySeams : public vtkPolyDataAlgorithm
{
public:
  static vtkGeometrySeams* New();
  vtkTypeMacro(vtkGeometrySeams, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How a ring is chosen among the candidates through the sector contour's edges.
  enum CandidateSearches
  {
    GLOBAL_CUT_FIRST = 0, ///< one max-flow first, the paper's loop only when it crosses twice
    EXHAUSTIVE = 1        ///< the paper's loop: one max-flow per edge of the sector contour
  };

  ///@{
  /// K + 1, the number of ring seams wanted. Default 15 (the paper's Fig. 2).
  vtkSetClampMacro(NumberOfRings, int, 1, 100000);
  vtkGetMacro(NumberOfRings, int);
  ///@}

  ///@{
  /// m: iso-contours at H = j / m, j = 0..m. Default 10.
  vtkSetClampMacro(NumberOfIsoContours, int, 1, 10000);
  vtkGetMacro(NumberOfIsoContours, int);
  ///@}

  ///@{
  /// n: sector contours traced from the handle to the fixed region. Default 8.
  vtkSetClampMacro(NumberOfSectors, int, 1, 10000);
  vtkGetMacro(NumberOfSectors, int);
  ///@}

  ///@{
  /// alpha, beta, gamma of Eq. 3: the weights of the saliency (normal-cone angle), ring-length
  /// normalisation and harmonic-field terms, each term in [0, 1]. Defaults 1, 0.25, 1 (Fig. 2).
  vtkSetMacro(Alpha, double);
  vtkGetMacro(Alpha, double);
  vtkSetMacro(Beta, double);
  vtkGetMacro(Beta, double);
  vtkSetMacro(Gamma, double);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /// How the candidates are searched (same rings up to ties). Default GLOBAL_CUT_FIRST.
  vtkSetClampMacro(CandidateSearch, int, GLOBAL_CUT_FIRST, EXHAUSTIVE);
  vtkGetMacro(CandidateSearch, int);
  void SetCandidateSearchToGlobalCutFirst() { this->SetCandidateSearch(GLOBAL_CUT_FIRST); }
  void SetCandidateSearchToExhaustive() { this->SetCandidateSearch(EXHAUSTIVE); }
  ///@}

  ///@{
  /// Names of the output arrays. Defaults "HarmonicField", "Sector", "RingSeam", "EdgeCost".
  vtkSetStringMacro(HarmonicFieldArrayName);
  vtkGetStringMacro(HarmonicFieldArrayName);
  vtkSetStringMacro(SectorArrayName);
  vtkGetStringMacro(SectorArrayName);
  vtkSetStringMacro(RingSeamArrayName);
  vtkGetStringMacro(RingSeamArrayName);
  vtkSetStringMacro(EdgeCostArrayName);
  vtkGetStringMacro(EdgeCostArrayName);
  ///@}

  /// Output 1: the iso- and sector contours.
  vtkPolyData* GetContours();

protected:
  vtkGeometrySeams();
  ~vtkGeometrySeams() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int NumberOfRings = 15;
  int NumberOfIsoContours = 10;
  int NumberOfSectors = 8;
  double Alpha = 1.0;
  double Beta = 0.25;
  double Gamma = 1.0;
  int CandidateSearch = GLOBAL_CUT_FIRST;
  char* HarmonicFieldArrayName = nullptr;
  char* SectorArrayName = nullptr;
  char* RingSeamArrayName = nullptr;
  char* EdgeCostArrayName = nullptr;

private:
  vtkGeometrySeams(const vtkGeometrySeams&) = delete;
  void operator=(const vtkGeometrySeams&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
