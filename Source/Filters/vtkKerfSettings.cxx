// Kerf's process-wide settings: the thread limit of Core's parallel loops, for Python and ParaView.
#include "vtkKerfSettings.h"

#include "Error.h"
#include "Threads.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

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
  if (threads == kerf::threadLimitSetting())
  {
    return;
  }
  try
  {
    kerf::setThreadLimit(threads);
  }
  catch (const kerf::Error& error)
  {
    vtkErrorMacro(<< "Cannot set the thread limit: " << error.what() << "; it stays " << kerf::threadLimitSetting()
                  << ".");
    return;
  }
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
  return kerf::hardwareThreads();
}

void vtkKerfSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThreadLimit: " << this->GetThreadLimit() << "\n";
  os << indent << "EffectiveThreadLimit: " << this->GetEffectiveThreadLimit() << "\n";
}
