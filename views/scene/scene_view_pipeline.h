#pragma once
// What SceneView draws with (scene_view.cpp builds it; scene_view_shape.cpp
// fills the deformed layer): the VTK pipeline behind the widget. Internal to
// views/scene.

#include <QVTKOpenGLStereoWidget.h>
#include <QVTKOpenGLWindow.h>
#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkArrowSource.h>
#include <vtkAxesActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGlyph3D.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkLabeledDataMapper.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPointData.h>
#include <vtkPointPicker.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "views/scene/scene_view.h"

namespace mozzi {
namespace views {

struct SceneView::Pipeline {
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkAxesActor> axes;
  vtkNew<vtkOrientationMarkerWidget> marker;
  // mesh layer (undeformed)
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPolyDataMapper> meshMapper;
  vtkNew<vtkActor> meshActor;
  vtkNew<vtkPolyData> nodes;
  vtkNew<vtkPolyDataMapper> nodeMapper;
  vtkNew<vtkActor> nodeActor;
  // selection
  vtkNew<vtkPolyData> selection;
  vtkNew<vtkPolyDataMapper> selectionMapper;
  vtkNew<vtkActor> selectionActor;
  // labels
  // Node labels, made when first shown (SceneView::setLabelsVisible): the
  // mapper allocates its text mappers up front, a few ms of a page's opening.
  vtkSmartPointer<vtkLabeledDataMapper> labelMapper;
  vtkSmartPointer<vtkActor2D> labelActor;
  // deformed layer: its own points (written per tick), the mesh's cells
  vtkNew<vtkPolyData> deformed;
  vtkNew<vtkPoints> deformedPoints;
  vtkNew<vtkDoubleArray> deformedCoords;
  vtkNew<vtkUnsignedCharArray> colours;  // RGB per node, from the peak displacement: set once per shape
  vtkNew<vtkPolyDataMapper> deformedMapper;
  vtkNew<vtkActor> deformedActor;
  vtkNew<vtkLookupTable> lut;
  vtkNew<vtkScalarBarActor> legend;
  // arrows at the arrow nodes: undeformed position, vector = displacement now
  vtkNew<vtkPolyData> arrowInput;
  vtkNew<vtkDoubleArray> arrowVectors;
  vtkNew<vtkArrowSource> arrow;
  vtkNew<vtkGlyph3D> glyphs;
  vtkNew<vtkPolyDataMapper> arrowMapper;
  vtkNew<vtkActor> arrowActor;
  vtkNew<vtkPointPicker> picker;
  // hit marker: a large node and an arrow ending at it
  vtkNew<vtkPolyData> hitNode;
  vtkNew<vtkPolyDataMapper> hitNodeMapper;
  vtkNew<vtkActor> hitNodeActor;
  vtkNew<vtkPolyData> hitArrowInput;
  vtkNew<vtkArrowSource> hitArrow;
  vtkNew<vtkDoubleArray> hitArrowVector;
  vtkNew<vtkGlyph3D> hitGlyph;
  vtkNew<vtkPolyDataMapper> hitArrowMapper;
  vtkNew<vtkActor> hitArrowActor;
  vtkNew<vtkBillboardTextActor3D> hitText;  // the point's DOF, beside the node, facing the camera
};

}  // namespace views
}  // namespace mozzi
