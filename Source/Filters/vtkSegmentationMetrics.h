/**
 * @class vtkSegmentationMetrics
 * @brief Compares two per-face segmentations of one mesh with the Princeton benchmark's metrics.
 *
 * Input array 0 is the segmentation being evaluated and input array 1 the reference (ground
 * truth), both integer labels on cells. They are selected with SetInputArrayToProcess: by default
 * array 0 is the cell array "Segment" of input 0 and array 1 the cell array "Segment" of input 1.
 * To compare two arrays of one mesh, leave input 1 unconnected and select array 1 on input 0,
 * e.g. SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human").
 * With two inputs, both must be the same mesh (same points and triangles).
 *
 * The output is a one-row vtkTable (Chen, Golovinskiy, Funkhouser, "A Benchmark for 3D Mesh
 * Segmentation", 2009; Kouhestani 2013, section 4), every value lower-is-better:
 * - CutDiscrepancy = (DCD(E => R) + DCD(R => E)) / average radius, with the directional parts
 *   CutDiscrepancyEvaluatedToReference and CutDiscrepancyReferenceToEvaluated. DCD(A => B) is the
 *   mean distance from A's cut vertices to B's cut, measured along mesh edges (the edge-graph
 *   approximation the benchmark itself uses); the average radius is the mean distance of the
 *   vertices to their centroid. When either segmentation has no cut, CutDiscrepancy is 0 (the
 *   benchmark's convention) and CutsCompared is 0.
 * - HammingDistance = (MissingRate + FalseAlarmRate) / 2, area-weighted, with the reference as
 *   ground truth.
 * - RandIndexError = 1 - Rand index over unordered face pairs, from the contingency table.
 * - GlobalConsistencyError and LocalConsistencyError, area-weighted.
 * - EvaluatedSegments, ReferenceSegments, ComparedFaces, CutsCompared.
 *
 * Labels need not be contiguous or in the same order. Label -1 marks an unlabelled face: it is
 * left out of the region metrics and its edges are not cuts. Polygons are triangulated, each
 * triangle taking its polygon's labels (face pairs then count triangles). Arrays of the wrong
 * length, non-integral or negative labels other than -1, two different meshes, and surfaces with
 * NaN coordinates are reported with vtkErrorMacro.
 */
#ifndef vtkSegmentationMetrics_h
#define vtkSegmentationMetrics_h

#include "KerfFiltersModule.h"
#include "vtkTableAlgorithm.h"

#include <memory>

class KERFFILTERS_EXPORT vtkSegmentationMetrics : public vtkTableAlgorithm
{
public:
  static vtkSegmentationMetrics* New();
  vtkTypeMacro(vtkSegmentationMetrics, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Connects the reference mesh (optional second input).
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkSegmentationMetrics();
  ~vtkSegmentationMetrics() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

private:
  vtkSegmentationMetrics(const vtkSegmentationMetrics&) = delete;
  void operator=(const vtkSegmentationMetrics&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
