// vtkHierarchicalFaceClustering: Garland et al. 2001 face clusters by dual-edge contraction, cut at k clusters or an
// error.
/**
 * @class vtkHierarchicalFaceClustering
 * @brief Hierarchical Face Clustering: Garland et al. 2001 face clusters by dual-edge contraction,
 * cut at k clusters or an error.
 *
 * Every face starts as a cluster; the dual edge with the smallest contraction cost E = E_fit + a1
 * E_dir + a2 E_shape (fit and direction quadrics, irregularity) is contracted until one cluster per
 * component remains. The merge tree is an output (field data MergeFirst, MergeSecond, MergeCost:
 * merge i joins two nodes into node n + i) and is cached: a new segment count or error only
 * relabels (field data Work = relabel). Surfaces of more than ExactClusterCount triangles start
 * their contractions in blocks of nearby triangles (about twice as fast at a million triangles).
 *
 * Output: the surface with the cell array "Segment" (name is a parameter), one label per
 * triangle numbered 0.. by first face, every segment one connected set of faces; field data
 * "SegmentCount" and the method's own figures.
 *
 * Errors (vtkErrorMacro, return 0; the output stays empty): surfaces refused by validation (NaN
 * coordinates, triangles repeating a point, non-manifold edges or vertices, inconsistent
 * orientation), a segment count below 1 or above the number of triangles, parameters out of range.
 * Documentation/filters/AutomaticSegmentation.md has the details.
 */
#ifndef vtkHierarchicalFaceClustering_h
#define vtkHierarchicalFaceClustering_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkHierarchicalFaceClustering : public vtkPolyDataAlgorithm
{
public:
  static vtkHierarchicalFaceClustering* New();
  vtkTypeMacro(vtkHierarchicalFaceClustering, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of clusters k; 0 cuts the tree at MaximumError instead. Default 6.
  vtkSetMacro(SegmentCount, int);
  vtkGetMacro(SegmentCount, int);
  ///@}

  ///@{
  /// With SegmentCount 0: the merges before the first whose cost exceeds this. Default 0.1.
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /// a1, the weight of the orientation error. Default 1.
  vtkSetMacro(DirectionWeight, double);
  vtkGetMacro(DirectionWeight, double);
  ///@}

  ///@{
  /// a2, the weight of the shape error. Default 0.1.
  vtkSetMacro(ShapeWeight, double);
  vtkGetMacro(ShapeWeight, double);
  ///@}

  ///@{
  /// Surfaces of at most this many triangles are contracted in the paper's greedy order from the
  /// first triangle on. On larger ones the contractions start inside blocks of BlockSize nearby
  /// triangles and the greedy order holds over the whole surface from about this many clusters
  /// on (a cut at fewer clusters comes from that part of the tree). Default 50000.
  vtkSetMacro(ExactClusterCount, int);
  vtkGetMacro(ExactClusterCount, int);
  ///@}
  ///@{
  /// Triangles per block where ExactClusterCount applies. Default 2048.
  vtkSetMacro(BlockSize, int);
  vtkGetMacro(BlockSize, int);
  ///@}
  ///@{
  /// Name of the output cell array. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

protected:
  vtkHierarchicalFaceClustering();
  ~vtkHierarchicalFaceClustering() override;

  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int SegmentCount = 6;
  double MaximumError = 0.1;
  double DirectionWeight = 1;
  double ShapeWeight = 0.1;
  int ExactClusterCount = 50000;
  int BlockSize = 2048;
  char* SegmentArrayName = nullptr;

private:
  vtkHierarchicalFaceClustering(const vtkHierarchicalFaceClustering&) = delete;
  void operator=(const vtkHierarchicalFaceClustering&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
