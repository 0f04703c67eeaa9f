// vtkEnsembleSegmentation: Automatic segmentation into k parts that several automatic segmentations agree on most.
/**
 * @class vtkEnsembleSegmentation
 * @brief Ensemble Segmentation: Automatic segmentation into k parts that several automatic
 * segmentations agree on most.
 *
 * Consensus cuts, spectral clustering, convex flooding, k-means and the watershed (each with its
 * default parameters, face clustering optional) segment the surface into k parts each; faces that
 * every member keeps together form atoms, and the atoms are merged across shared edges by average
 * linkage of the members' co-association (the weighted fraction of members that put two faces in
 * one segment; Fred and Jain 2005's evidence accumulation) until k segments remain. A member's
 * weight is its vote; 0 leaves it out. Each boundary between two segments is then re-cut by a
 * minimum cut within a band around it (Katz and Tal 2003's fuzzy-region cut), so that it takes the
 * short and concave way nearby instead of the members' jagged votes.
 *
 * Output: the surface with the cell array "Segment" (name is a parameter), one label per
 * triangle numbered 0.. by first face, every segment one connected set of faces; field data
 * "SegmentCount" and the method's own figures ("Members": the segmentations that voted,
 * "Atoms": the groups of faces they all keep together); with ChooseSegmentCount also "CountScores",
 * per count from MinimumSegmentCount up, the mean 1 - Rand index of the ensemble at that count
 * against all the members (on a surface of one component; the smallest was chosen; empty where the
 * surface is within ConvexTolerance of its convex hull and stays one segment).
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): surfaces refused by validation (NaN
 * coordinates, triangles repeating a point, non-manifold edges or vertices, inconsistent
 * orientation), a segment count below 1 or above the number of triangles, with
 * ChooseSegmentCount a minimum below 2, a maximum below the minimum, above the number of
 * triangles or more than 40 counts, a ConvexTolerance outside [0, 1), a negative or
 * non-finite weight, all weights 0, a negative or non-finite BoundaryBand or ConvexWeight.
 * Documentation/filters/AutomaticSegmentation.md has the details.
 */
#ifndef vtkEnsembleSegmentation_h
#define vtkEnsembleSegmentation_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>
#include <vector>

class vtkFieldData;
namespace kerf
{
class Surface;
struct EnsembleSegmentationOptions;
}

class KERFFILTERS_EXPORT vtkEnsembleSegmentation : public vtkPolyDataAlgorithm
{
public:
  static vtkEnsembleSegmentation* New();
  vtkTypeMacro(vtkEnsembleSegmentation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of segments k (at least 1, at most the number of faces). Default 6.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// Choose the number of segments from the surface instead of SegmentCount: the ensemble runs at
  /// every count from MinimumSegmentCount to MaximumSegmentCount and keeps the one nearest, in
  /// mean 1 - Rand index, to all its members' segmentations at all those counts. Costs the
  /// ensemble's time once per count. Default off.
  vtkSetMacro(ChooseSegmentCount, bool);
  vtkGetMacro(ChooseSegmentCount, bool);
  vtkBooleanMacro(ChooseSegmentCount, bool);
  ///@}

  ///@{
  /// Build one merge tree for every count instead of an ensemble at SegmentCount: each member runs
  /// at every count from MinimumSegmentCount to MaximumSegmentCount and all those segmentations vote
  /// in one co-association, whose average-linkage tree is cut at SegmentCount. The tree is kept, so
  /// a new SegmentCount (or ChooseSegmentCount, which then takes the cut nearest to all the
  /// members) only re-labels: field data "Work" says "hierarchy" or "relabel". The output also
  /// carries the tree: "MergeFirst", "MergeSecond" (the atoms naming the two groups of each merge,
  /// the second joining the first; the atoms are the segments at SegmentCount = Atoms with
  /// BoundaryBand 0) and "MergeLinkage" (each merge's mean co-association), and "CountScores".
  /// SegmentCount above the atoms gives the atoms. On a surface of several components the members
  /// share each count by area and one count is chosen for the whole surface. A new Boundary Band,
  /// Convex Weight or Convex Tolerance builds the tree again (the scores of its cuts depend on
  /// them). Default off.
  vtkSetMacro(UseHierarchy, bool);
  vtkGetMacro(UseHierarchy, bool);
  vtkBooleanMacro(UseHierarchy, bool);
  ///@}

  ///@{
  /// The counts ChooseSegmentCount chooses among (2 <= minimum <= maximum, at most 40 counts;
  /// each component of a surface with several chooses its own), and the counts the members of
  /// UseHierarchy run at (each component with its share). Defaults 5 and 11.
  vtkSetMacro(MinimumSegmentCount, int);
  vtkGetMacro(MinimumSegmentCount, int);
  vtkSetMacro(MaximumSegmentCount, int);
  vtkGetMacro(MaximumSegmentCount, int);
  ///@}

  ///@{
  /// With ChooseSegmentCount: a component whose vertices all lie within this fraction of its
  /// bounding box's diagonal from its convex hull has no parts and stays one segment (a sphere, a
  /// planar patch). 0 gives every component a count in the range. Default 0.01.
  vtkSetMacro(ConvexTolerance, double);
  vtkGetMacro(ConvexTolerance, double);
  ///@}

  ///@{
  /// The vote of the consensus cuts (vtkConsensusCutSegmentation's method). Default 1.
  vtkSetMacro(ConsensusCutsWeight, double);
  vtkGetMacro(ConsensusCutsWeight, double);
  ///@}

  ///@{
  /// The vote of spectral clustering (vtkSpectralSegmentation's method). Default 1.
  vtkSetMacro(SpectralWeight, double);
  vtkGetMacro(SpectralWeight, double);
  ///@}

  ///@{
  /// The vote of convex flooding (vtkConvexFlooding's method). Default 1.
  vtkSetMacro(ConvexFloodingWeight, double);
  vtkGetMacro(ConvexFloodingWeight, double);
  ///@}

  ///@{
  /// The vote of k-means (vtkKMeansSegmentation's method). Default 1.
  vtkSetMacro(KMeansWeight, double);
  vtkGetMacro(KMeansWeight, double);
  ///@}

  ///@{
  /// The vote of the watershed (vtkWatershedSegmentation's method). Default 1.
  vtkSetMacro(WatershedWeight, double);
  vtkGetMacro(WatershedWeight, double);
  ///@}

  ///@{
  /// The vote of hierarchical face clustering (vtkHierarchicalFaceClustering's method). Default 0:
  /// it lowered the ensemble's accuracy on the Princeton benchmark.
  vtkSetMacro(FaceClusteringWeight, double);
  vtkGetMacro(FaceClusteringWeight, double);
  ///@}

  ///@{
  /// The vote of core extraction (vtkCoreExtractionSegmentation's method, with its own number of
  /// parts). Default 0: it lowered the ensemble's accuracy on the Princeton benchmark.
  vtkSetMacro(CoreExtractionWeight, double);
  vtkGetMacro(CoreExtractionWeight, double);
  ///@}

  ///@{
  /// Faces weigh by their area in the linkage instead of once each (the benchmark's Rand index
  /// counts faces). Default off.
  vtkSetMacro(AreaWeighted, bool);
  vtkGetMacro(AreaWeighted, bool);
  vtkBooleanMacro(AreaWeighted, bool);
  ///@}

  ///@{
  /// Half-width of the band in which each boundary is re-cut, as a fraction of the square root of
  /// the smaller neighbouring segment's area; 0 keeps the linkage's boundaries. Default 0.4.
  vtkSetMacro(BoundaryBand, double);
  vtkGetMacro(BoundaryBand, double);
  ///@}

  ///@{
  /// How much a convex edge's bend counts against a concave one's when the boundaries are re-cut
  /// (Katz and Tal 2003's eta; 1: alike). Default 0.1.
  vtkSetMacro(ConvexWeight, double);
  vtkGetMacro(ConvexWeight, double);
  ///@}

  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkEnsembleSegmentation();
  ~vtkEnsembleSegmentation() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int SegmentCount = 6;
  bool ChooseSegmentCount = false;
  bool UseHierarchy = false;
  int MinimumSegmentCount = 5;
  int MaximumSegmentCount = 11;
  double ConvexTolerance = 0.01;
  double ConsensusCutsWeight = 1.0;
  double SpectralWeight = 1.0;
  double ConvexFloodingWeight = 1.0;
  double KMeansWeight = 1.0;
  double WatershedWeight = 1.0;
  double FaceClusteringWeight = 0.0;
  double CoreExtractionWeight = 0.0;
  bool AreaWeighted = false;
  double BoundaryBand = 0.4;
  double ConvexWeight = 0.1;
  char* SegmentArrayName = nullptr;

private:
  vtkEnsembleSegmentation(const vtkEnsembleSegmentation&) = delete;
  void operator=(const vtkEnsembleSegmentation&) = delete;

  std::vector<int> CutHierarchy(
    const kerf::Surface& surface, const kerf::EnsembleSegmentationOptions& options, vtkFieldData* fieldData);

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
