// The kerf program's commands (one file each in Commands/) and what they share.
#pragma once

#include "KerfArguments.h"
#include "KerfScene.h"

#include <vtkSmartPointer.h>

#include <chrono>
#include <string>

class vtkAlgorithm;
class vtkPolyData;

namespace kerf
{

int RunInfo(const Arguments& args);
int RunConvert(const Arguments& args);
int RunRender(const Arguments& args);
int RunDescriptors(const Arguments& args);
int RunCut(const Arguments& args);
int RunShowcase(const Arguments& args, const char* program);
int RunBenchmark(const Arguments& args);
int RunUnwrap(const Arguments& args);
int RunSegment(const Arguments& args);
/// The methods `kerf segment` takes, for its help and errors.
std::string SegmentMethodNames();

/// Updates an algorithm; its VTK error becomes a CommandError "<what>: <message>".
void RunAlgorithm(vtkAlgorithm* algorithm, const std::string& what);
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& fileName);
void WriteMesh(vtkPolyData* mesh, const std::string& fileName);
/// The render options (--array, --map, --directions, --caption, --azimuth, --elevation,
/// --range-fraction, --size).
SceneOptions ParseSceneOptions(const Arguments& args);
/// Renders offscreen into a PNG; a clear CommandError when no display is available.
void RenderPNG(vtkPolyData* mesh, const SceneOptions& options, const std::string& fileName);
/// Fails with a CommandError naming xvfb-run when there is no X display to render with.
void RequireDisplay();
double MillisecondsSince(std::chrono::steady_clock::time_point start);
/// The names of a mesh's point arrays, separated by commas.
std::string PointArrayNames(vtkPolyData* mesh);

} // namespace kerf
