// The stroke cut that `kerf cut` and `kerf showcase` run: descriptors, constraints, field, cut.
#pragma once

#include "KerfArguments.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineCut.h"
#include "vtkStrokeConstraints.h"
#include "vtkSurfaceDescriptors.h"

#include <vtkNew.h>

#include <string>
#include <utility>
#include <vector>

class vtkPolyData;

namespace kerf
{

/// The stages of a stroke cut, kept alive together so that their outputs stay valid.
struct CutPipeline
{
  vtkNew<vtkSurfaceDescriptors> descriptors;
  vtkNew<vtkStrokeConstraints> constraints;
  vtkNew<vtkHarmonicField> field;
  vtkNew<vtkIsolineCut> cut;
  std::vector<std::pair<std::string, double>> milliseconds; ///< per stage, in the order run

  /// mesh -> (descriptors ->) stroke constraints -> harmonic field -> cut nearest the stroke, with
  /// the cut options (--weighting, --formulation, --iso-value, --samples, --offset, --soft-weight).
  /// The descriptors only add output arrays.
  void Run(vtkPolyData* mesh, vtkPolyData* stroke, const Arguments& args, bool withDescriptors);
  /// Left: the field with isolines, the stroke and its constraints; right: the segments and the cut.
  void Render(vtkPolyData* stroke, const std::string& caption, const std::string& file);
};

/// "2 segments (5000, 14536 triangles)".
std::string SegmentSizes(vtkPolyData* surface);
/// "1 curve (1 closed), length 0.4".
std::string CutSummary(vtkPolyData* curve);

} // namespace kerf
