#include "render/FrameRenderer.hpp"

#include "core/Error.hpp"
#include "io/AtomicFile.hpp"
#include "render/ColourMap.hpp"
#include "surface/VtkConversion.hpp"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkClipPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFloatArray.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkOutlineSource.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace poro {

namespace {

/// A splat that reads as a ball of the particle's radius: a disc shaded by the normal's component towards the
/// viewer, sqrt(1 - d^2), over an ambient third (ParaView's "Sphere" preset fades to black at the rim, which on a
/// lattice leaves only small dots).
const char* const kSphereSplat = "//VTK::Color::Impl\n"
                                 "float dist = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                                 "if (dist > 1.0) { discard; } else {\n"
                                 "  float scale = 0.35 + 0.65 * sqrt(1.0 - dist);\n"
                                 "  ambientColor *= scale;\n"
                                 "  diffuseColor *= scale;\n"
                                 "}\n";

vtkSmartPointer<vtkLookupTable> lookupTable(const SetStyle& style, const std::array<double, 2>& range) {
  const ColourMap& map = ColourMap::named(style.colourMap);
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  for (int k = 0; k < 256; ++k) {
    const Vec3 c = map.at(k / 255.0);
    table->SetTableValue(k, c[0], c[1], c[2], 1.0);
  }
  table->SetTableRange(range[0], range[1]);
  table->Build();
  return table;
}

void setValues(vtkPolyData* poly, const std::vector<double>& values) {
  vtkNew<vtkFloatArray> array;
  array->SetName("value");
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) array->SetValue(static_cast<vtkIdType>(k), static_cast<float>(values[k]));
  poly->GetPointData()->SetScalars(array);
}

vtkSmartPointer<vtkActor> actorOf(vtkAlgorithmOutput* input, vtkPolyData* data, const SetStyle& style,
                                  vtkLookupTable* table, bool coloured) {
  vtkNew<vtkPolyDataMapper> mapper;
  if (input) mapper->SetInputConnection(input);
  else mapper->SetInputData(data);
  mapper->SetScalarVisibility(coloured);
  if (coloured) {
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(style.colour[0], style.colour[1], style.colour[2]);
  actor->GetProperty()->SetOpacity(style.opacity);
  // Some ambient light: a colour map's light end stays light on faces turned away from the lights.
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.75);
  return actor;
}

} // namespace

struct FrameRenderer::Impl {
  RenderSettings settings;
  CameraView camera;
  std::map<std::string, std::array<double, 2>> ranges;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;

  vtkSmartPointer<vtkPlane> clipPlane() const {
    auto plane = vtkSmartPointer<vtkPlane>::New();
    plane->SetOrigin(settings.clip->origin.data());
    plane->SetNormal(settings.clip->normal.data());
    return plane;
  }
  void addSurface(const SceneLayer& layer, vtkLookupTable* table, bool coloured);
  void addCap(const SceneLayer& layer, vtkLookupTable* table, bool coloured);
  void addParticles(const SceneLayer& layer, vtkLookupTable* table, bool coloured);
  void addContainers(const SceneLayer& layer, const Vec3& up);
  void addLegend(const SetStyle& style, vtkLookupTable* table, int index);
  void addTimeLabel(const Scene& scene);
};

FrameRenderer::FrameRenderer(const RenderSettings& settings, const CameraView& camera,
                             std::map<std::string, std::array<double, 2>> ranges)
    : impl_(std::make_unique<Impl>()) {
  impl_->settings = settings;
  impl_->camera = camera;
  impl_->ranges = std::move(ranges);
  vtkRenderWindow* window = impl_->window;
  window->SetOffScreenRendering(1);
  window->SetSize(settings.width, settings.height);
  window->SetAlphaBitPlanes(1); // depth peeling: translucent water in front of and behind bodies
  window->SetMultiSamples(0);
  window->AddRenderer(impl_->renderer);
  vtkRenderer* renderer = impl_->renderer;
  renderer->SetBackground(settings.background.data());
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(6);
  renderer->SetOcclusionRatio(0.0);
  renderer->UseFXAAOn();
  vtkNew<vtkLightKit> lights; // key, fill, back and head light as in ParaView: shapes read without harsh shadows
  lights->AddLightsToRenderer(renderer);
}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::Impl::addSurface(const SceneLayer& layer, vtkLookupTable* table, bool coloured) {
  if (layer.surface.empty()) return;
  vtkSmartPointer<vtkPolyData> poly = toPolyData(layer.surface);
  if (coloured) setValues(poly, layer.values);
  vtkSmartPointer<vtkActor> actor;
  if (settings.clip && std::find(settings.clip->sets.begin(), settings.clip->sets.end(), layer.style->set) !=
                           settings.clip->sets.end()) {
    vtkNew<vtkClipPolyData> clip;
    clip->SetInputData(poly);
    clip->SetClipFunction(clipPlane());
    clip->InsideOutOn(); // keep the side the normal points away from
    actor = actorOf(clip->GetOutputPort(), nullptr, *layer.style, table, coloured);
    addCap(layer, table, coloured);
  } else {
    actor = actorOf(nullptr, poly, *layer.style, table, coloured);
  }
  if (layer.style->set == "fluid") {
    actor->GetProperty()->SetSpecular(0.5);
    actor->GetProperty()->SetSpecularPower(40.0);
  }
  renderer->AddActor(actor);
}

void FrameRenderer::Impl::addCap(const SceneLayer& layer, vtkLookupTable* table, bool coloured) {
  if (layer.cap.empty()) return;
  vtkSmartPointer<vtkPolyData> cap = toPolyData(layer.cap);
  if (coloured) setValues(cap, layer.capValues);
  renderer->AddActor(actorOf(nullptr, cap, *layer.style, table, coloured && !layer.capValues.empty()));
}

void FrameRenderer::Impl::addParticles(const SceneLayer& layer, vtkLookupTable* table, bool coloured) {
  // A non-finite position (SceneBuilder leaves them out already) would make the bounds, and so the camera's
  // clipping range, NaN: such particles are skipped with their values.
  std::vector<double> values;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  for (std::size_t p = 0; p < layer.particles.size(); ++p) {
    if (!layer.particles[p].allFinite()) continue;
    points->InsertNextPoint(layer.particles[p].data());
    if (coloured && p < layer.values.size()) values.push_back(layer.values[p]);
  }
  if (points->GetNumberOfPoints() == 0) return;
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  if (coloured) setValues(poly, values);
  vtkNew<vtkPointGaussianMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScaleFactor(layer.particleRadius);
  mapper->SetSplatShaderCode(kSphereSplat);
  mapper->EmissiveOff();
  mapper->SetScalarVisibility(coloured);
  if (coloured) {
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(layer.style->colour[0], layer.style->colour[1], layer.style->colour[2]);
  actor->GetProperty()->SetOpacity(layer.style->opacity);
  renderer->AddActor(actor);
}

void FrameRenderer::Impl::addContainers(const SceneLayer& layer, const Vec3& up) {
  for (const auto& box : layer.containers) {
    vtkNew<vtkOutlineSource> outline;
    outline->SetBounds(box[0].x(), box[1].x(), box[0].y(), box[1].y(), box[0].z(), box[1].z());
    vtkSmartPointer<vtkActor> edges = actorOf(outline->GetOutputPort(), nullptr, *layer.style, nullptr, false);
    edges->GetProperty()->SetColor(0.45, 0.45, 0.45);
    edges->GetProperty()->SetLineWidth(1.5f);
    renderer->AddActor(edges);
    // The floor: the face gravity points to, a particle diameter behind the inner face (inside the wall layers)
    // so that the water's bottom, which lies on the face, does not flicker through it.
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (std::abs(up[a]) > std::abs(up[axis])) axis = a;
    const Vec3 extent = box[1] - box[0];
    Vec3 origin = box[0];
    if (up[axis] < 0.0) origin[axis] = box[1][axis];
    origin[axis] -= (up[axis] < 0.0 ? -1.0 : 1.0) * 2.0 * layer.particleRadius;
    Vec3 p1 = origin, p2 = origin;
    p1[(axis + 1) % 3] += extent[(axis + 1) % 3];
    p2[(axis + 2) % 3] += extent[(axis + 2) % 3];
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(origin.data());
    floor->SetPoint1(p1.data());
    floor->SetPoint2(p2.data());
    vtkSmartPointer<vtkActor> ground = actorOf(floor->GetOutputPort(), nullptr, *layer.style, nullptr, false);
    ground->GetProperty()->SetColor(0.85 * layer.style->colour[0], 0.85 * layer.style->colour[1],
                                    0.85 * layer.style->colour[2]);
    renderer->AddActor(ground);
  }
}

namespace {
// Legends stand side by side from the right edge; a title reaches about 0.04 of the width left of its bar.
constexpr double legendLeft = 0.90, legendPitch = 0.11, legendTitleOverhang = 0.04;
} // namespace

double FrameRenderer::legendsWidth(int legends) {
  return legends > 0 ? 1.0 - legendLeft + legendTitleOverhang + legendPitch * (legends - 1) : 0.0;
}

void FrameRenderer::Impl::addLegend(const SetStyle& style, vtkLookupTable* table, int index) {
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(table);
  bar->SetTitle((style.colourBy == "v" ? std::string("speed |v|") : style.colourBy).c_str());
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.3g");
  bar->SetOrientationToVertical();
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->SetPosition(legendLeft - legendPitch * index, 0.12);
  bar->SetWidth(0.09);
  bar->SetHeight(0.76);
  bar->SetBarRatio(0.3);
  bar->UnconstrainedFontSizeOn();
  for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0.1, 0.1, 0.1);
    text->SetFontSize(std::max(10, settings.height / 40));
    text->ShadowOff();
    text->ItalicOff();
    text->BoldOff();
  }
  renderer->AddActor2D(bar);
}

void FrameRenderer::Impl::addTimeLabel(const Scene& scene) {
  vtkNew<vtkTextActor> label;
  label->SetInput(("t = " + scene.timeName + " s").c_str());
  label->GetTextProperty()->SetFontSize(std::max(12, settings.height / 25));
  label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->GetTextProperty()->SetVerticalJustificationToTop();
  label->SetPosition(0.02, 0.97);
  renderer->AddActor2D(label);
}

void FrameRenderer::render(const Scene& scene, const std::filesystem::path& png) {
  Impl& m = *impl_;
  m.renderer->RemoveAllViewProps();
  int legends = 0;
  for (const SceneLayer& layer : scene.layers) {
    const SetStyle& style = *layer.style;
    const bool coloured = !style.colourBy.empty() && !layer.values.empty();
    vtkSmartPointer<vtkLookupTable> table;
    if (coloured) {
      const auto range = m.ranges.count(style.set) ? m.ranges.at(style.set) : std::array<double, 2>{0.0, 1.0};
      table = lookupTable(style, range);
    }
    m.addContainers(layer, scene.up);
    m.addSurface(layer, table, coloured);
    m.addParticles(layer, table, coloured);
    if (coloured && m.settings.legend) m.addLegend(style, table, legends++);
  }
  if (m.settings.timeLabel) m.addTimeLabel(scene);

  vtkCamera* camera = m.renderer->GetActiveCamera();
  camera->SetPosition(m.camera.position.data());
  camera->SetFocalPoint(m.camera.focalPoint.data());
  camera->SetViewUp(m.camera.viewUp.data());
  camera->SetViewAngle(m.camera.viewAngle);
  m.renderer->ResetCameraClippingRange();
  m.window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(m.window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  // Into a temporary sibling, renamed over the frame when complete: a viewer or the movie encoder never reads a
  // half-written frame, and a failed write leaves the old frame as it was. Created here first, so that the check
  // below is about this write and a missing or read-only directory gets the OS's reason.
  const std::filesystem::path temporary = temporarySibling(png);
  if (!std::ofstream(temporary))
    throw OutputError(png.string() + ": cannot create file (" + std::strerror(errno) + ")");
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetCompressionLevel(9);
  writer->SetFileName(temporary.c_str());
  writer->Write();
  std::error_code ec;
  if (writer->GetErrorCode() != vtkErrorCode::NoError || std::filesystem::file_size(temporary, ec) == 0 || ec) {
    const std::string reason = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    std::filesystem::remove(temporary, ec);
    throw OutputError(png.string() + ": cannot write the PNG file (" + reason + ")");
  }
  commitTemporaryFile(temporary, png);
}

} // namespace poro
