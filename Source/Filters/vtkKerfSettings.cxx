// Kerf's process-wide settings: the thread limit of Core's parallel loops, for Python and ParaView.
#include "vtkKerfSettings.h"

#include "Threads.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <thread>

vtkKerfSettings* vtkKerfSettings::New()
{
  vtkKerfSettings* instance = vtkKerfSettings::GetInstance();
  instance->Register(nullptr);
  return instance;
}

vtkKerfSettings* vtkKerfSettings::GetInstance()
{
  // Created on first use and released at exit; never deleted while the process runs.
  static vtkSmartPointer<vtkKerfSettings> instance = [] {
    vtkKerfSettings* created = new vtkKerfSettings;
    created->InitializeObjectBase();
    return vtkSmartPointer<vtkKerfSettings>::Take(created);
  }();
  return instance;
}

void vtkKerfSettings::SetThreadLimit(int threads)
{
  if (threads < 0)
  {
    vtkErrorMacro(<< "Cannot set the thread limit: it must be 0 (KERF_NUM_THREADS, else every core) or at least "
                     "1, got "
                  << threads << "; it stays " << kerf::threadLimitSetting() << ".");
    return;
  }
  if (threads == kerf::threadLimitSetting())
  {
    return;
  }
  kerf::setThreadLimit(threads);
  this->Modified();
}

int vtkKerfSettings::GetThreadLimit()
{
  return kerf::threadLimitSetting();
}

int vtkKerfSettings::GetEffectiveThreadLimit()
{
  return kerf::threadLimit();
}

int vtkKerfSettings::GetNumberOfCores()
{
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void vtkKerfSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThreadLimit: " << this->GetThreadLimit() << "\n";
  os << indent << "EffectiveThreadLimit: " << this->GetEffectiveThreadLimit() << "\n";
}
