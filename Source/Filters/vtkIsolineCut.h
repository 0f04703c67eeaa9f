/**
 * @class vtkIsolineCut
 * @brief Chooses a cut as an isoline of a scalar field: at a given value, the best-scored of
 * sampled values (ROI Scissor), or the component nearest to a stroke (SeamCut); labels the two
 * sides.
 *
 * The field is a point array of the input surface, selected with SetInputArrayToProcess(0, 0, 0,
 * vtkDataObject::FIELD_ASSOCIATION_POINTS, name) (default "HarmonicField"). Modes:
 * - VALUE: the isoline f = IsoValue. Changing IsoValue slides the cut (SeamCut, section 3):
 *   only this filter re-executes, and it keeps its converted surface between executions.
 * - BEST_SCORE: NumberOfCandidates values sampled uniformly inside the field's range (default
 *   50), each scored by S_i = sum_T |I_i cap T| / |I_i| |grad f_T| (ROI Scissor, section 4.2); the
 *   best one is chosen.
 * - NEAR_STROKE: the isoline f = IsoValue, keeping only its connected component nearest to the
 *   stroke on the second input (SeamCut, section 2.1.3).
 *
 * Outputs:
 * 0. the chosen isoline as polylines (closed loops closed, one orientation throughout), with
 *    cell arrays IsoValue, Score (of that component), Length and Closed;
 * 1. the surface with the cell array "Segment" (name is a parameter): the two sides of the cut,
 *    split further into connected components; only the chosen components cut;
 * 2. a table of the candidates (IsoValue, Score, Length; BEST_SCORE only, else empty).
 *
 * Isolines are extracted with vertices equal to the value counted as above it, so flat regions
 * and vertex crossings give neither duplicate points nor gaps. Errors: a missing or
 * multi-component field array, NaN field values, NEAR_STROKE without a stroke, a constant field
 * in BEST_SCORE mode, and surfaces refused by validation (the filter needs an edge-manifold,
 * consistently oriented surface).
 */
#ifndef vtkIsolineCut_h
#define vtkIsolineCut_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class vtkTable;

class KERFFILTERS_EXPORT vtkIsolineCut : public vtkPolyDataAlgorithm
{
public:
  static vtkIsolineCut* New();
  vtkTypeMacro(vtkIsolineCut, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    VALUE = 0,
    BEST_SCORE = 1,
    NEAR_STROKE = 2
  };

  ///@{
  /// How the isoline is chosen. Default VALUE.
  vtkSetClampMacro(Mode, int, VALUE, NEAR_STROKE);
  vtkGetMacro(Mode, int);
  void SetModeToValue() { this->SetMode(VALUE); }
  void SetModeToBestScore() { this->SetMode(BEST_SCORE); }
  void SetModeToNearStroke() { this->SetMode(NEAR_STROKE); }
  ///@}

  ///@{
  /// The iso-value (VALUE and NEAR_STROKE). Default 0.
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /// Number of sampled iso-values m (BEST_SCORE). Default 50.
  vtkSetClampMacro(NumberOfCandidates, int, 1, 100000);
  vtkGetMacro(NumberOfCandidates, int);
  ///@}

  ///@{
  /// Name of the output cell array of segment labels. Default "Segment".
  vtkSetStringMacro(SegmentArrayName);
  vtkGetStringMacro(SegmentArrayName);
  ///@}

  /// The surface with segment labels (output 1) and the candidate table (output 2).
  vtkPolyData* GetLabelledSurface();
  vtkTable* GetCandidates();

  /// Connects the stroke for NEAR_STROKE (optional second input: its points are used).
  void SetStrokeConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkIsolineCut();
  ~vtkIsolineCut() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  int Mode = VALUE;
  double IsoValue = 0.0;
  int NumberOfCandidates = 50;
  char* SegmentArrayName = nullptr;

private:
  vtkIsolineCut(const vtkIsolineCut&) = delete;
  void operator=(const vtkIsolineCut&) = delete;

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
