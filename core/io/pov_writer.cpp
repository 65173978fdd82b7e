#include "core/io/pov_writer.h"

#include "core/io/pending_file.h"
#include "core/io/pov_mapping.h"
#include "core/io/shape_text/shape_text.h"
#include "core/scene/material_blend.h"

#include <cmath>
#include <sstream>
#include <tuple>
#include <vector>

namespace prism {

namespace {

using sc::num;

// POV-Ray's vector literal: <x, y, z> (named apart from sc::vec, the .sc
// writer's, which a unity batch may bring into the same file).
std::string povVector(const Vec3& v) {
  return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">";
}

std::string materialName(std::uint32_t index) { return "Prism_M" + std::to_string(index); }

// POV-Ray's `matrix` takes the map's columns (its rows act on row vectors)
// and then the offset: x -> linear x + offset.
std::string matrix(const Mat3& linear, const Vec3& offset) {
  std::string text = "matrix <";
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row)
      text += num(linear[column][row]) + ", ";
  }
  return text + num(offset.x) + ", " + num(offset.y) + ", " + num(offset.z) + ">";
}

// The size of everything the camera and the lights can reach, which sets the
// lights' fade distance (pov_mapping.h).
double sceneSize(const Scene& scene) {
  Aabb box;
  box.extend(scene.camera.eye);
  for (const Light& l : scene.lights)
    box.extend(l.position);
  for (const PrimitiveRef& ref : scene.allPrimitives())
    box.extend(scene.bounds(ref));
  const double size = glm::length(box.extent());
  return std::isfinite(size) && size > 0.0 ? size : 1.0;
}

class PovText {
public:
  PovText(std::ostream& out, const Scene& scene) : out_(out), scene_(scene) {}

  void header(const std::string& text) {
    std::istringstream lines(text);
    std::string comment;
    while (std::getline(lines, comment))
      out_ << "// " << comment << "\n";
    out_ << "#version 3.7;\n";
  }

  void globals() {
    out_ << "#ifndef (Prism_Depth) #declare Prism_Depth = 5; #end\n";
    // adc_bailout 0: POV-Ray would otherwise drop rays of small weight,
    // which Prism traces (without --bailout).
    out_ << "global_settings { assumed_gamma 1.0 max_trace_level Prism_Depth adc_bailout 0 "
            "ambient_light rgb "
         << povVector(scene_.ambient) << " }\n";
    out_ << "background { rgb " << povVector(scene_.background) << " }\n";
    // POV-Ray's constant fog is exp(-d / distance) L + (1 - exp(-d / distance)) C, a
    // ray that meets nothing taking the fog's colour: Prism's fog exactly.
    if (scene_.fog.active())
      out_ << "fog { fog_type 1 distance " << num(1.0 / scene_.fog.density) << " color rgb "
           << povVector(scene_.fog.color) << " }\n";
  }

  // The vectors of Prism's camera (core/scene/camera.cpp) written out, with
  // neither look_at nor angle, which would have POV-Ray rebuild them in its
  // left-handed frame. POV-Ray's ray through pixel (ix, iy) is direction +
  // ((ix + 0.5) / W - 0.5) right + (0.5 - (iy + 0.5) / H) up, so right and up
  // span the whole image plane: twice Prism's half-widths. The aspect ratio is
  // POV-Ray's image size, so +W and +H act like Prism's --size.
  void camera() {
    const CameraSpec& c = scene_.camera;
    const Vec3 forward = glm::normalize(c.lookat - c.eye);
    const Vec3 right = glm::normalize(glm::cross(forward, c.up));
    const Vec3 up = glm::cross(right, forward);
    const double halfHeight = std::tan(glm::radians(c.fov) * 0.5);
    out_ << "// Prism camera: eye " << povVector(c.eye) << " lookat " << povVector(c.lookat)
         << " up " << povVector(c.up) << " fov " << num(c.fov) << " (vertical)\n";
    out_ << "camera {\n  perspective\n  location " << povVector(c.eye) << "\n  direction "
         << povVector(forward) << "\n  right " << povVector(right) << " * ("
         << num(2.0 * halfHeight) << " * image_width / image_height)\n  up " << povVector(up)
         << " * " << num(2.0 * halfHeight) << "\n}\n";
  }

  void lights() {
    const double fade = povFadeDistance(sceneSize(scene_));
    const double scale = povLightScale(fade);
    for (const Light& l : scene_.lights) {
      out_ << "light_source { " << povVector(l.position) << " color rgb "
           << povVector(l.intensity * scale) << " fade_distance " << num(fade)
           << " fade_power 2 }\n";
    }
  }

  // Image textures and the triangles' surface coordinates are not written
  // (a POV-Ray image_map would need the picture's path and a uv_mapping of
  // each mesh): each material that has an image says so, in a comment.
  void materials() {
    if (!scene_.triangleUvs.empty())
      out_ << "// the triangles' per-vertex uv (triangle_uv) are not converted\n";
    for (std::size_t i = 0; i < scene_.materials.size(); ++i) {
      const PovMaterial m = povMaterialOf(scene_.materials[i]);
      if (!m.exact)
        out_ << "// " << materialName(std::uint32_t(i))
             << " transmits everything: POV-Ray shows no diffuse light on it\n";
      if (const ImageMap& map = scene_.materials[i].image; map.active() && scene_.images)
        out_ << "// " << materialName(std::uint32_t(i)) << " has the image texture "
             << scene_.images->info(map.image).path
             << ", which is not converted: POV-Ray shows its colour untextured\n";
      out_ << "#declare " << materialName(std::uint32_t(i)) << " = material {\n";
      if (scene_.materials[i].texture.active())
        patterned(scene_.materials[i]);
      else
        out_ << "  texture {\n" << surface(m, "    ") << "  }\n";
      if (m.transmit > 0.0) {
        out_ << "  interior { ior " << num(m.ior);
        if (m.fadeDistance > 0.0)
          out_ << " fade_distance " << num(m.fadeDistance) << " fade_power 1001 fade_color rgb "
               << povVector(m.fadeColor);
        out_ << " }\n";
      }
      out_ << "}\n";
    }
  }

  // A material's pigment and finish, each line indented by `pad`.
  static std::string surface(const PovMaterial& m, const std::string& pad) {
    std::ostringstream out;
    out << pad << "pigment { rgbt <" << num(m.color.r) << ", " << num(m.color.g) << ", "
        << num(m.color.b) << ", " << num(m.transmit) << "> }\n"
        << pad << "finish { ambient " << num(m.ambient) << " diffuse " << num(m.diffuse)
        << " specular " << num(m.specular);
    if (m.specular > 0.0) out << " roughness " << num(m.roughness);
    out << " reflection { " << num(m.reflection) << " } }\n";
    return out.str();
  }

  // A textured material as POV-Ray's pattern over the two ends' textures
  // (docs/vs-povray.md, What differs): checker is the same pattern, stripes and
  // gradient are POV-Ray's gradient x with a texture_map, noise, marble and
  // wood are POV-Ray's bozo, marble and wood, which are alike, not equal.
  void patterned(const Material& material) {
    const Texture& t = material.texture;
    const bool checker = t.kind == TextureKind::Checker;
    const std::string pad = checker ? "      " : "        ";
    const std::string low = surface(povMaterialOf(textureBlend(material, 0.0)), pad);
    const std::string high = surface(povMaterialOf(textureBlend(material, 1.0)), pad);
    switch (t.kind) {
    case TextureKind::Noise:
    case TextureKind::Marble:
    case TextureKind::Wood:
      out_ << "  // approximate: POV-Ray's "
           << (t.kind == TextureKind::Noise ? std::string_view("bozo") : textureKindName(t.kind))
           << " is not Prism's " << textureKindName(t.kind) << " pattern\n";
      break;
    default: break;
    }
    out_ << "  texture {\n";
    if (checker) {
      out_ << "    checker\n    texture {\n"
           << low << "    }\n    texture {\n"
           << high << "    }\n";
    } else {
      switch (t.kind) {
      case TextureKind::Stripes: out_ << "    gradient x scale <2, 1, 1>\n"; break;
      case TextureKind::Gradient: out_ << "    gradient x\n"; break;
      case TextureKind::Noise: out_ << "    bozo\n"; break;
      case TextureKind::Marble: out_ << "    marble turbulence 1\n"; break;
      default: out_ << "    wood turbulence 0.1\n"; break;
      }
      // Stripes: the low end on [0, 0.5) of the doubled gradient, the high
      // end on [0.5, 1).
      const bool stripes = t.kind == TextureKind::Stripes;
      out_ << "    texture_map {\n      [0 texture {\n" << low << "      }]\n";
      if (stripes) out_ << "      [0.5 texture {\n" << low << "      }]\n";
      if (stripes) out_ << "      [0.5 texture {\n" << high << "      }]\n";
      out_ << "      [1 texture {\n" << high << "      }]\n    }\n";
    }
    // POV-Ray shows a pattern moved by `matrix` M at p as the pattern at
    // M^-1 p; Prism's is at (linear p + offset) / scale.
    const Mat3 linear = t.linear / t.scale;
    const double det = glm::determinant(linear);
    if (det != 0.0 && std::isfinite(det)) {
      const Mat3 m = glm::inverse(linear) + Mat3(0.0); // + 0: no -0 written
      const Vec3 offset = -(m * (t.offset / t.scale)) + Vec3(0.0);
      out_ << "    matrix <";
      for (int column = 0; column < 3; ++column)
        out_ << num(m[column][0]) << ", " << num(m[column][1]) << ", " << num(m[column][2]) << ", ";
      out_ << num(offset.x) << ", " << num(offset.y) << ", " << num(offset.z) << ">\n";
    } else {
      out_ << "    // approximate: the texture space is degenerate, left untransformed\n";
    }
    out_ << "  }\n";
  }

  // Every kind through one overload of `all`, so a kind added to ShapeKinds
  // without a POV-Ray form here does not compile (rather than vanish from
  // the converted scene).
  void shapes() {
    std::apply([&](const auto&... kinds) { (all(kinds), ...); }, scene_.storage.vectors);
  }

private:
  static std::string material(std::uint32_t index) {
    return "material { " + materialName(index) + " }";
  }

  template <class Kind> void all(const std::vector<Kind>& shapes) {
    for (const Kind& shape : shapes)
      one(shape);
  }

  void one(const Sphere& s) {
    out_ << "sphere { " << povVector(s.center) << ", " << num(s.radius) << " "
         << material(s.material) << " }\n";
  }

  // The unit sphere, carried into place by the ellipsoid's map.
  void one(const Ellipsoid& e) {
    out_ << "sphere { <0, 0, 0>, 1 " << matrix(e.objectToWorld, e.center) << " "
         << material(e.material) << " }\n";
  }

  // POV-Ray's polygon takes concave polygons as they are (it counts
  // crossings, like Prism); the first vertex is repeated to close it.
  void one(const Polygon& p) {
    const Vec3* v = scene_.polygonVertices.data() + p.firstVertex;
    out_ << "polygon { " << p.vertexCount + 1;
    for (std::uint32_t i = 0; i < p.vertexCount; ++i)
      out_ << ", " << povVector(v[i]);
    out_ << ", " << povVector(v[0]) << " " << material(p.material) << " }\n";
  }

  // An open cone between its two circles; an elliptic one (the scene
  // language allows any transform) as the unit-height cone of its own frame,
  // carried into place by its matrix.
  void one(const Cone& c) { cone(c, true, c.material); }

  // A capped cone is POV-Ray's cone without `open`; one of equal radii its
  // cylinder.
  void one(const CappedCone& c) { cone(c.side, false, c.material); }

  void cone(const Cone& c, bool open, std::uint32_t materialIndex) {
    const Mat3& m = c.objectToWorld;
    const bool cylinder = !open && c.baseRadius == c.apexRadius;
    const char* const ending = open ? " open " : " ";
    out_ << (cylinder ? "cylinder { " : "cone { ");
    const auto ends = [&](const std::string& base, const std::string& apex, double unit) {
      out_ << base << ", ";
      if (!cylinder) out_ << num(c.baseRadius * unit) << ", ";
      out_ << apex << ", " << num(c.apexRadius * unit) << ending;
    };
    if (isCircular(c)) {
      ends(povVector(c.objectToWorldOffset), povVector(c.objectToWorldOffset + m[2]),
           glm::length(m[0]));
    } else {
      ends("<0, 0, 0>", "<0, 0, 1>", 1.0);
      out_ << matrix(m, c.objectToWorldOffset) << " ";
    }
    out_ << material(materialIndex) << " }\n";
  }

  // POV-Ray's box by two corners; one in its own frame carried by its matrix.
  void one(const Box& b) {
    out_ << "box { " << povVector(b.lo) << ", " << povVector(b.hi) << " ";
    if (!isWorldAligned(b))
      out_ << matrix(b.frame.objectToWorld, b.frame.objectToWorldOffset) << " ";
    out_ << material(b.material) << " }\n";
  }

  // POV-Ray's disc by centre, normal and radius; an elliptic one as the unit
  // frame's disc carried by its matrix.
  void one(const Disc& d) {
    const Mat3& m = d.frame.objectToWorld;
    out_ << "disc { ";
    if (isCircular(d)) {
      out_ << povVector(d.frame.objectToWorldOffset) << ", " << povVector(d.normal) << ", "
           << num(d.radius * glm::length(m[0])) << " ";
    } else {
      out_ << "<0, 0, 0>, <0, 0, 1>, " << num(d.radius) << " "
           << matrix(m, d.frame.objectToWorldOffset) << " ";
    }
    out_ << material(d.material) << " }\n";
  }

  // POV-Ray's quadric takes A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x +
  // H y + I z + J as <A, B, C>, <D, E, F>, <G, H, I>, J: its second vector is
  // xy, xz, yz, where Prism's D E F are xy, yz, xz. The clip box is POV-Ray's
  // clipped_by, given before the matrix so that the matrix carries both.
  void one(const Quadric& q) {
    const std::array<double, 10> k = givenCoefficients(q);
    out_ << "quadric { <" << num(k[0]) << ", " << num(k[1]) << ", " << num(k[2]) << ">, <"
         << num(k[3]) << ", " << num(k[5]) << ", " << num(k[4]) << ">, <" << num(k[6]) << ", "
         << num(k[7]) << ", " << num(k[8]) << ">, " << num(k[9]) << " clipped_by { box { "
         << povVector(q.lo) << ", " << povVector(q.hi) << " } } ";
    if (!isUnplaced(q)) out_ << matrix(q.frame.objectToWorld, q.frame.objectToWorldOffset) << " ";
    out_ << material(q.material) << " }\n";
  }

  // POV-Ray's torus lies around its y axis, Prism's around the frame's z: the
  // matrix takes POV-Ray's x, y and z to the frame's x, z and y (a mirror,
  // which the torus does not see). `sturm` has POV-Ray solve the quartic
  // with Sturm sequences, as robust as Prism's root isolation.
  void one(const Torus& t) {
    const Mat3& m = t.objectToWorld;
    out_ << "torus { " << num(t.major) << ", " << num(t.minor) << " sturm "
         << matrix(Mat3(m[0], m[2], m[1]), t.objectToWorldOffset) << " " << material(t.material)
         << " }\n";
  }

  // POV-Ray's union, intersection and difference are Prism's: a
  // difference takes the later objects from the first, and each object keeps
  // its own material (the subtracted ones' shows on the surfaces they cut).
  void one(const Csg& node) {
    out_ << csgOpName(node.op) << " {\n";
    for (const CsgOperand& operand : operandsOf(node, scene_.arrays())) {
      out_ << "  ";
      std::visit(
          [&](const auto& shape) {
            if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>)
              one(scene_.csgNodes[shape.index]);
            else
              one(shape);
          },
          operand.shape);
    }
    out_ << "}\n";
  }

  // POV-Ray's blob of sphere components, whose field is Prism's (blob.h);
  // one with a frame carried by its matrix. `sturm` has POV-Ray solve the
  // quartics with Sturm sequences, the more robust of its two solvers.
  void one(const Blob& b) {
    out_ << "blob { threshold " << num(b.threshold) << "\n";
    for (const BlobComponent& c : componentsOf(b, scene_.arrays()))
      out_ << "  sphere { " << povVector(c.center) << ", " << num(c.radius) << ", strength "
           << num(c.strength) << " }\n";
    out_ << "  sturm ";
    if (b.placed) out_ << matrix(b.frame.objectToWorld, b.frame.objectToWorldOffset) << " ";
    out_ << material(b.material) << "\n}\n";
  }

  // A closed mesh operand of CSG: POV-Ray's mesh, with an inside_vector so
  // POV-Ray treats it as a solid (it counts crossings along that direction).
  void one(const SolidMesh& m) {
    out_ << "mesh {\n";
    for (const Triangle& t : trianglesOf(m, scene_.arrays()))
      triangle(t);
    out_ << "  inside_vector <0, 0, 1> " << material(m.material) << "\n}\n";
  }

  // Triangles as POV-Ray meshes: one per run of triangles of one material
  // (a mesh has one material), which POV-Ray stores and bounds more cheaply
  // than as many separate objects.
  void all(const std::vector<Triangle>& triangles) {
    for (std::size_t i = 0; i < triangles.size();) {
      const std::uint32_t run = triangles[i].material;
      out_ << "mesh {\n";
      for (; i < triangles.size() && triangles[i].material == run; ++i)
        triangle(triangles[i]);
      out_ << "  " << material(run) << "\n}\n";
    }
  }

  void triangle(const Triangle& t) {
    out_ << (t.smooth() ? "  smooth_triangle { " : "  triangle { ");
    for (std::size_t k = 0; k < 3; ++k) {
      out_ << (k ? ", " : "") << povVector(scene_.meshVertices[t.vertex[k]]);
      if (t.smooth()) out_ << ", " << povVector(scene_.meshNormals[t.normal[k]]);
    }
    out_ << " }\n";
  }

  std::ostream& out_;
  const Scene& scene_;
};

} // namespace

void writePov(std::ostream& out, const Scene& scene, const std::string& header) {
  PovText text(out, scene);
  text.header(header);
  text.globals();
  text.camera();
  text.lights();
  text.materials();
  text.shapes();
}

void savePov(const std::filesystem::path& path, const Scene& scene, const std::string& header) {
  writeFileAtomically(path, [&](std::ostream& out) { writePov(out, scene, header); });
}

} // namespace prism
