// Regression image: the bundled camel in eight segments by consensus cuts.
#include "KerfTestUtilities.h"
#include "vtkConsensusCutSegmentation.h"

#include <vtkNew.h>

int TestConsensusCutSegmentationImage(int argc, char* argv[])
{
  vtkNew<vtkConsensusCutSegmentation> segmentation;
  segmentation->SetSegmentCount(8);
  return kerf::test::CamelSegmentationImageTest(argc, argv, segmentation);
}
