// Regression image: the bundled camel segmented by core extraction, with the number of parts its own: the head and
// neck, the body and the four legs (six segments, asserted besides the picture).
#include "KerfTestUtilities.h"
#include "vtkCoreExtractionSegmentation.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>

int TestCoreExtractionSegmentationImage(int argc, char* argv[])
{
  vtkNew<vtkCoreExtractionSegmentation> segmentation;
  const int result = kerf::test::CamelSegmentationImageTest(argc, argv, segmentation);
  vtkDataArray* count =
    vtkDataArray::SafeDownCast(segmentation->GetOutput()->GetFieldData()->GetAbstractArray("SegmentCount"));
  if (!count || count->GetComponent(0, 0) != 6.0)
  {
    std::cerr << "expected 6 segments, got " << (count ? count->GetComponent(0, 0) : -1.0) << std::endl;
    return EXIT_FAILURE;
  }
  return result;
}
