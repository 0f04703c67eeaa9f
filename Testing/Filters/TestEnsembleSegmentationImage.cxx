// Regression image: the bundled camel in eight segments by the ensemble segmentation.
#include "KerfTestUtilities.h"
#include "vtkEnsembleSegmentation.h"

#include <vtkNew.h>

int TestEnsembleSegmentationImage(int argc, char* argv[])
{
  vtkNew<vtkEnsembleSegmentation> segmentation;
  segmentation->SetSegmentCount(8);
  return kerf::test::CamelSegmentationImageTest(argc, argv, segmentation);
}
