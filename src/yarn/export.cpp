#include "yarn/export.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <bit>
#include <cmath>
#include <numbers>
#include <ostream>

namespace skein {
namespace {

void write_header(const YarnModel& model, std::ostream& out) {
  out << fmt::format("# skein yarn model: {} yarn pieces, {} points, yarn radius {:.6g}\n",
                     model.pieces(), model.point.size(), model.radius);
}

// Rotation-minimising normals along a polyline by double reflection.
std::vector<Point3> rotation_minimising_normals(const std::vector<Point3>& x) {
  const std::size_t n = x.size();
  std::vector<Point3> tangent(n), normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    Point3 t = x[std::min(i + 1, n - 1)] - x[i > 0 ? i - 1 : 0];
    tangent[i] = t.norm() > 0 ? Point3(t.normalized()) : Point3::UnitX();
  }
  normal[0] = tangent[0].unitOrthogonal();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    Point3 v1 = x[i + 1] - x[i];
    float c1 = v1.squaredNorm();
    if (c1 < 1e-20f) {
      normal[i + 1] = normal[i];
      continue;
    }
    Point3 rl = normal[i] - (2 / c1) * v1.dot(normal[i]) * v1;
    Point3 tl = tangent[i] - (2 / c1) * v1.dot(tangent[i]) * v1;
    Point3 v2 = tangent[i + 1] - tl;
    float c2 = v2.squaredNorm();
    normal[i + 1] = c2 < 1e-20f ? rl : Point3(rl - (2 / c2) * v2.dot(rl) * v2);
  }
  for (std::size_t i = 0; i < n; ++i)
    normal[i] = (normal[i] - normal[i].dot(tangent[i]) * tangent[i]).normalized();
  return normal;
}

}  // namespace

void write_yarn_obj(const YarnModel& model, std::ostream& out) {
  write_header(model, out);
  for (const Point3& p : model.point)
    out << fmt::format("v {:.6g} {:.6g} {:.6g}\n", p.x(), p.y(), p.z());
  for (std::uint32_t p = 0; p < model.pieces(); ++p) {
    out << fmt::format("o yarn{}\nl", p + 1);
    for (std::uint32_t i = model.piece_first[p]; i < model.piece_first[p + 1]; ++i)
      out << ' ' << i + 1;
    out << '\n';
  }
}

void write_yarn_tubes_obj(const YarnModel& model, std::ostream& out, int sides) {
  write_header(model, out);
  std::uint64_t base = 1;
  for (std::uint32_t p = 0; p < model.pieces(); ++p) {
    std::vector<Point3> x(model.point.begin() + model.piece_first[p],
                          model.point.begin() + model.piece_first[p + 1]);
    if (x.size() < 2) continue;
    std::vector<Point3> normal = rotation_minimising_normals(x);
    for (std::size_t i = 0; i < x.size(); ++i) {
      Point3 t = (x[std::min(i + 1, x.size() - 1)] - x[i > 0 ? i - 1 : 0]).normalized();
      Point3 binormal = t.cross(normal[i]);
      for (int k = 0; k < sides; ++k) {
        float a = 2 * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(sides);
        Point3 v = x[i] + model.radius * (std::cos(a) * normal[i] + std::sin(a) * binormal);
        out << fmt::format("v {:.6g} {:.6g} {:.6g}\n", v.x(), v.y(), v.z());
      }
    }
    out << fmt::format("o yarn{}\n", p + 1);
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      for (int k = 0; k < sides; ++k) {
        std::uint64_t a = base + i * sides + k, b = base + i * sides + (k + 1) % sides;
        out << fmt::format("f {} {} {} {}\n", a, b, b + sides, a + sides);
      }
    base += x.size() * sides;
  }
}

void write_yarn_ply(const YarnModel& model, std::ostream& out) {
  std::uint64_t edges = 0;
  for (std::uint32_t p = 0; p < model.pieces(); ++p)
    edges += std::max<std::uint32_t>(model.piece_first[p + 1] - model.piece_first[p], 1) - 1;
  out << "ply\nformat binary_little_endian 1.0\n"
      << fmt::format("comment skein yarn model, yarn radius {:.6g}\n", model.radius)
      << fmt::format("element vertex {}\n", model.point.size())
      << "property float x\nproperty float y\nproperty float z\n"
      << fmt::format("element edge {}\n", edges)
      << "property int vertex1\nproperty int vertex2\nend_header\n";
  static_assert(std::endian::native == std::endian::little, "PLY is written little-endian");
  for (const Point3& p : model.point) {
    float xyz[3] = {p.x(), p.y(), p.z()};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  for (std::uint32_t p = 0; p < model.pieces(); ++p)
    for (std::uint32_t i = model.piece_first[p]; i + 1 < model.piece_first[p + 1]; ++i) {
      std::int32_t e[2] = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(i + 1)};
      out.write(reinterpret_cast<const char*>(e), sizeof e);
    }
}

}  // namespace skein
