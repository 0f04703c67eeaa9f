// kerf benchmark: the command-line front end of the benchmark runner (vtkSegmentationBenchmark).
#include "KerfCommands.h"

#include "vtkSegmentationBenchmark.h"

#include <vtkNew.h>
#include <vtksys/SystemTools.hxx>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace kerf
{

int RunBenchmark(const Arguments& args)
{
  if (!args.positional.empty() || !args.has("data"))
  {
    throw CommandError{ "benchmark needs --data FOLDER (see --help)" };
  }
  vtkNew<vtkSegmentationBenchmark> benchmark;
  benchmark->SetDataDirectory(args.get("data").c_str());
  benchmark->SetMethod(args.get("method", "human").c_str());
  benchmark->SetMethodParameters(args.get("parameters").c_str());
  const int jobs = args.integer("jobs", 1, 1, 64);
  benchmark->SetNumberOfJobs(jobs);
  std::size_t count = 0;
  if (args.has("models"))
  {
    std::istringstream list(args.get("models"));
    std::string item;
    while (std::getline(list, item, ','))
    {
      try
      {
        benchmark->AddModel(std::stoi(item));
        ++count;
      }
      catch (const std::exception&)
      {
        throw CommandError{ "--models expects ids separated by commas, got '" + args.get("models") + "'" };
      }
    }
  }
  else
  {
    std::string error;
    count = vtkSegmentationBenchmark::FindModels(args.get("data"), error).size();
    if (count == 0)
    {
      throw CommandError{ error.empty() ? args.get("data") + " holds no models" : error };
    }
  }
  const std::string folder = args.get("output", "kerf-benchmark");
  benchmark->SetOutputDirectory(folder.c_str());
  benchmark->SetWritePictures(!args.has("no-pictures"));
  if (benchmark->GetWritePictures())
  {
    RequireDisplay();
  }
  benchmark->PrintProgressOn();
  std::cout << "Kerf benchmark: method " << benchmark->GetMethod() << " on " << count << " models of "
            << args.get("data") << " with " << jobs << (jobs == 1 ? " process" : " processes") << std::endl;
  const auto start = std::chrono::steady_clock::now();
  RunAlgorithm(benchmark, "benchmark");
  std::cout << "\n" << benchmark->GetSummary();
  std::cout << "\nresults:  " << vtksys::SystemTools::CollapseFullPath(folder + "/results.csv")
            << "\nsummary:  " << vtksys::SystemTools::CollapseFullPath(folder + "/summary.csv");
  if (benchmark->GetWritePictures())
  {
    std::cout << "\npictures: " << vtksys::SystemTools::CollapseFullPath(folder + "/pictures");
  }
  std::cout << "\ntime:     " << std::fixed << std::setprecision(1) << MillisecondsSince(start) / 1000.0 << " s"
            << std::endl;
  return 0;
}

} // namespace kerf
