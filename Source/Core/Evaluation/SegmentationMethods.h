// The segmentation methods the benchmark runner knows: name, parameters, protocol and how each segments a model.
#pragma once

#include "Evaluation/BenchmarkCase.h"
#include "Evaluation/MethodParameters.h"

#include <functional>
#include <string>
#include <vector>

namespace kerf
{

/// What a method made of one model.
struct MethodOutput
{
  std::vector<int> labels; ///< per face
  int inputs = 0;          ///< strokes or clicks it was given (interactive methods)
};

/// A segmentation method the runner knows, and the protocol it is scored with.
struct SegmentationMethod
{
  enum class Protocol
  {
    /// The humans against each other (the benchmark's human baseline); `segment` is unused.
    HumanBaseline,
    /// Input simulated from one human: every human of the model in turn is the input and the
    /// others the references (leave one out, as the human baseline); also scored against the
    /// input human itself (the fidelity: how well the user's intent is reproduced).
    Interactive,
    /// The mesh and the number of segments only (nSeg-ByModel.txt), scored against every human.
    Automatic
  };
  std::string name;
  std::string description;
  std::vector<std::string> parameters;
  Protocol protocol = Protocol::Interactive;
  /// Segments a model; `input` is the human the input is simulated from (Interactive) or null.
  std::function<MethodOutput(const BenchmarkCase&, const std::vector<int>* input, const MethodParameters&)> segment;
};

/// Every method, in the order the help lists them.
const std::vector<SegmentationMethod>& segmentationMethods();
/// The method of that name; throws kerf::Error listing the names for any other.
const SegmentationMethod& findSegmentationMethod(const std::string& name);

} // namespace kerf
