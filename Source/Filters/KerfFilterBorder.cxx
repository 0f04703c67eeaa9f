// The border every Kerf filter's RequestData and setters run inside: exceptions become one vtkErrorMacro and a 0
// return; the surface loaded; the ports of a surface with optional points.
#include "KerfFilterBorder.h"

#include "Error.h"

#include <vtkAlgorithm.h>
#include <vtkInformation.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>

#include <new>

namespace kerf
{

namespace
{
std::string sentence(std::string message)
{
  if (!message.empty() && message.back() != '.')
  {
    message += '.';
  }
  return message;
}
} // namespace

namespace
{
// Runs `body`; false, with the message of whatever it threw, if it threw.
bool runCatching(const std::function<void()>& body, std::string& message)
{
  try
  {
    body();
    return true;
  }
  catch (const std::bad_alloc&)
  {
    message = "out of memory";
  }
  catch (const std::exception& e)
  {
    message = e.what();
  }
  catch (...)
  {
    message = "an unknown failure";
  }
  return false;
}
} // namespace

int RunGuarded(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& body)
{
  std::string message;
  if (runCatching(body, message))
  {
    algorithm->UpdateProgress(1.0);
    return 1;
  }
  vtkErrorWithObjectMacro(algorithm, << what << ": " << sentence(message));
  return 0;
}

void GuardSetter(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& setter)
{
  std::string message;
  if (!runCatching(setter, message))
  {
    vtkErrorWithObjectMacro(algorithm, << what << ": " << sentence(message) << " Nothing was changed.");
  }
}

void LoadSurface(SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements)
{
  std::string error;
  if (!surface.Load(input, requirements, error))
  {
    throw Error(error);
  }
}

int FillSurfaceAndOptionalPointsPorts(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

} // namespace kerf
