#include "render/RenderSettings.hpp"

#include "core/Dictionary.hpp"
#include "physics/FieldNames.hpp"
#include "render/ColourMap.hpp"
#include "sph/ParticleSet.hpp"

#include <Eigen/Geometry>

#include <sstream>

namespace poro {

namespace {

SetStyle defaultStyle(const std::string& set, bool porousBodies) {
  SetStyle s;
  s.set = set;
  s.where = "system/renderDict (default)";
  if (set == "fluid") {
    s.colour = Vec3(0.30, 0.55, 0.90);
    s.opacity = porousBodies ? 0.35 : 0.85;
  } else if (set == "porous") {
    s.colourBy = field::saturation;
    s.colourMap = "wetness";
  } else {
    s.colour = Vec3(0.80, 0.80, 0.80);
  }
  return s;
}

/// The field a surface of `set` carries (fluidSurface: the velocity; porous bodies: the saturation; walls: none).
std::string surfaceField(const std::string& set) {
  return set == "fluid" ? field::v : set == "porous" ? field::saturation : "";
}

SetStyle readStyle(const Dictionary& dict, SetStyle s) {
  s.where = dict.where("colourBy");
  const std::string show = dict.getWord("show", {"surface", "particles", "none"},
                                        s.show == SetStyle::Show::Surface ? "surface" : "particles");
  s.show = show == "surface" ? SetStyle::Show::Surface : show == "particles" ? SetStyle::Show::Particles
                                                                              : SetStyle::Show::None;
  if (dict.has("colourBy")) {
    const std::string field = surfaceField(s.set);
    if (s.show == SetStyle::Show::Surface) {
      std::vector<std::string> choices{"none"};
      if (!field.empty()) choices.push_back(field);
      s.colourBy = dict.getWord("colourBy", choices);
    } else {
      s.colourBy = dict.getString("colourBy"); // any field of the particle file, checked when it is read
    }
    if (s.colourBy == "none") s.colourBy.clear();
  }
  s.colourMap = dict.getWord("colourMap", ColourMap::names(), s.colourMap);
  if (dict.has("range")) {
    const auto range = dict.getReals("range", 2, {});
    if (!(range[0] < range[1])) dict.fail("range", "expected [min, max] with min < max");
    s.range = std::array<double, 2>{range[0], range[1]};
  } else if (s.colourBy != field::saturation) {
    s.range.reset();
  }
  // A map or range without a field to colour by would be silently ignored.
  for (const char* key : {"colourMap", "range"})
    if (s.colourBy.empty() && dict.has(key))
      dict.fail(key, std::string("given, but colourBy is none") + (dict.has("colourBy") ? "" : " (the default here)") +
                         ", so the set is drawn in its solid colour; remove " + key + " or set colourBy");
  s.colour = dict.getVec3("colour", s.colour);
  for (int c = 0; c < 3; ++c)
    if (s.colour[c] < 0.0 || s.colour[c] > 1.0) dict.fail("colour", "expected red, green and blue in [0, 1]");
  s.opacity = dict.getReal("opacity", s.opacity, Range{0.0, 1.0, true, false});
  dict.checkUnknownKeys();
  return s;
}

} // namespace

std::string viewUpProblem(const Vec3& viewUp, const Vec3& viewDirection) {
  // Parallel within about 0.06 degrees: VTK could not tell which way is up in the picture.
  if (viewUp.cross(viewDirection).norm() > 1e-3 * viewUp.norm() * viewDirection.norm()) return "";
  std::ostringstream msg;
  msg << "expected a direction not parallel to the view direction focalPoint - position = ["
      << viewDirection.transpose() << "], got [" << viewUp.transpose()
      << "]; viewUp is the direction that points up in the picture";
  return msg.str();
}

RenderSettings readRenderSettings(const std::filesystem::path& caseDir, bool porousBodies) {
  RenderSettings s;
  s.fluid = defaultStyle("fluid", porousBodies);
  s.porous = defaultStyle("porous", porousBodies);
  s.porous.range = std::array<double, 2>{0.0, 1.0};
  s.boundary = defaultStyle("boundary", porousBodies);
  const std::filesystem::path path = caseDir / "system" / "renderDict";
  if (!std::filesystem::exists(path)) return s;

  const Dictionary dict = Dictionary::read(path.string());
  const auto size = dict.getReals("imageSize", 2, {double(s.width), double(s.height)}, Range::closed(16, 8192));
  s.width = static_cast<int>(size[0]);
  s.height = static_cast<int>(size[1]);
  if (s.width != size[0] || s.height != size[1]) dict.fail("imageSize", "expected whole numbers of pixels");
  s.background = dict.getVec3("background", s.background);
  for (int c = 0; c < 3; ++c)
    if (s.background[c] < 0.0 || s.background[c] > 1.0)
      dict.fail("background", "expected red, green and blue in [0, 1]");
  s.frameRate = dict.getReal("frameRate", s.frameRate, Range::closed(0.1, 120.0));
  s.timeLabel = dict.getBool("timeLabel", s.timeLabel);
  s.legend = dict.getBool("legend", s.legend);
  if (const auto camera = dict.optionalSubDict("camera")) {
    for (const char* key : {"position", "focalPoint", "viewUp"}) camera->markKnown(key); // optional, no default
    if (camera->has("position")) s.camera.position = camera->getVec3("position");
    if (camera->has("focalPoint")) s.camera.focalPoint = camera->getVec3("focalPoint");
    if (camera->has("viewUp")) s.camera.viewUp = camera->getVec3("viewUp");
    if (s.camera.viewUp && s.camera.viewUp->norm() == 0.0) camera->fail("viewUp", "expected a non-zero direction");
    if (s.camera.position && s.camera.focalPoint && *s.camera.position == *s.camera.focalPoint)
      camera->fail("position", "expected a position other than the focal point");
    s.camera.viewUpWhere = camera->where("viewUp");
    if (s.camera.viewUp && s.camera.position && s.camera.focalPoint) {
      const std::string problem = viewUpProblem(*s.camera.viewUp, *s.camera.focalPoint - *s.camera.position);
      if (!problem.empty()) camera->fail("viewUp", problem);
    }
    s.camera.viewAngle = camera->getReal("viewAngle", s.camera.viewAngle, Range::open(0.0, 180.0));
    camera->checkUnknownKeys();
  }
  for (SetStyle* style : {&s.fluid, &s.porous, &s.boundary})
    if (const auto sub = dict.optionalSubDict(style->set)) *style = readStyle(*sub, *style);
  if (const auto clip = dict.optionalSubDict("clip")) {
    ClipSettings c;
    c.origin = clip->getVec3("origin");
    c.normal = clip->getVec3("normal");
    if (c.normal.norm() == 0.0) clip->fail("normal", "expected a non-zero direction");
    c.normal.normalize();
    if (clip->has("sets")) c.sets = clip->getWordList("sets", {"fluid", "porous", "boundary"});
    clip->checkUnknownKeys();
    s.clip = c;
  }
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
