/**
 * @class vtkDrawnStrokeAlgorithm
 * @brief The strokes drawn on the surface in a filter's panel (in ParaView, Kerf's sketch widget:
 * hold Ctrl and drag over the surface), for the filters that take strokes (vtkStrokeCut,
 * vtkStrokeConstraints, vtkEasyMeshCut, vtkRegionGrowing). Abstract.
 *
 * The drawn strokes are three lists: their points one after another (DrawnStrokePoints), the
 * number of points of each stroke (DrawnStrokeSizes; all the points one stroke when it is empty)
 * and each stroke's label (DrawnStrokeLabels; 0 for all when it is empty; the filters that grow
 * parts read it, -1 marking Easy Mesh Cut's override strokes). AddDrawnStroke appends a stroke to
 * all three. Drawn strokes replace the typed strokes of the panel (StrokePoints, or Easy Mesh
 * Cut's foreground and background points) where they are given: all of them for the harmonic
 * cuts, those of the same label for the filters that grow parts. A stroke input connected to
 * input 1 replaces both.
 */
#ifndef vtkDrawnStrokeAlgorithm_h
#define vtkDrawnStrokeAlgorithm_h

#include "KerfFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class vtkPoints;

namespace kerf
{
class DrawnStrokeList;
}

class KERFFILTERS_EXPORT vtkDrawnStrokeAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkDrawnStrokeAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The points of the drawn strokes, one stroke after another. Default: none.
  void SetNumberOfDrawnStrokePoints(int count);
  int GetNumberOfDrawnStrokePoints() const;
  void SetDrawnStrokePoint(int index, double x, double y, double z);
  ///@}

  ///@{
  /// The number of points of each drawn stroke, in order. Default: none (all the points one
  /// stroke).
  void SetNumberOfDrawnStrokeSizes(int count);
  int GetNumberOfDrawnStrokeSizes() const;
  void SetDrawnStrokeSize(int index, int size);
  int GetDrawnStrokeSize(int index) const;
  ///@}

  ///@{
  /// The label of each drawn stroke, in order: 0 and up for the filters that grow parts
  /// (background 0, foreground 1), -1 for an override stroke of vtkEasyMeshCut. Default: none
  /// (every stroke 0).
  void SetNumberOfDrawnStrokeLabels(int count);
  int GetNumberOfDrawnStrokeLabels() const;
  void SetDrawnStrokeLabel(int index, int label);
  int GetDrawnStrokeLabel(int index) const;
  ///@}

  /// Appends a drawn stroke of `points` (at least one) with `label`.
  void AddDrawnStroke(vtkPoints* points, int label = 0);
  /// Forgets every drawn stroke.
  void RemoveAllDrawnStrokes();

protected:
  vtkDrawnStrokeAlgorithm();
  ~vtkDrawnStrokeAlgorithm() override;

  std::unique_ptr<kerf::DrawnStrokeList> DrawnStrokes;

private:
  vtkDrawnStrokeAlgorithm(const vtkDrawnStrokeAlgorithm&) = delete;
  void operator=(const vtkDrawnStrokeAlgorithm&) = delete;
};

#endif
