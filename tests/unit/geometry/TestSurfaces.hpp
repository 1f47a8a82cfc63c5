#pragma once
/// Closed test surfaces built in code (cube, octahedron, icosphere, torus), writers for the five file formats
/// sampleParticles reads, and exact reference answers that do not use the sampler's parity rule: the enclosed
/// volume (divergence theorem), the winding number (solid angles), which is 1 inside and 0 outside, and for
/// convex meshes the side of every face plane.

#include "geometry/TriangleMesh.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>

namespace poro::test {

constexpr double kPi = 3.14159265358979323846;

/// The box [min, max] as 12 triangles, outward. Each face is split along a diagonal, which rows of a lattice
/// whose spacing divides the box pass through exactly (the degenerate rows the sampler must count once).
inline TriangleMesh cubeMesh(const Vec3& min, const Vec3& max) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back(k & 1 ? max.x() : min.x(), k & 2 ? max.y() : min.y(), k & 4 ? max.z() : min.z());
  // Corner k has bits (x, y, z); each face as a quad counter-clockwise from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.triangles.push_back({std::size_t(q[0]), std::size_t(q[1]), std::size_t(q[2])});
    m.triangles.push_back({std::size_t(q[0]), std::size_t(q[2]), std::size_t(q[3])});
  }
  return m;
}

/// The octahedron |x - c|_1 = h, outward.
inline TriangleMesh octahedronMesh(const Vec3& c, double h) {
  TriangleMesh m;
  for (int d = 0; d < 3; ++d)
    for (double s : {-1.0, 1.0}) m.vertices.push_back(c + s * h * Vec3::Unit(d));
  // Vertex 2d is c - h e_d, 2d + 1 is c + h e_d; one face per octant.
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        std::array<std::size_t, 3> t = {std::size_t(sx), std::size_t(2 + sy), std::size_t(4 + sz)};
        if ((sx + sy + sz) % 2 == 0) std::swap(t[1], t[2]); // outward in every octant
        m.triangles.push_back(t);
      }
  return m;
}

/// An icosahedron refined `levels` times (20 * 4^levels faces), vertices on the sphere |x - c| = radius, outward.
inline TriangleMesh icosphereMesh(const Vec3& c, double radius, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : v) p.normalize();
  std::vector<std::array<std::size_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                               {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                               {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                               {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    const auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return middle[key] = v.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    for (const auto& tri : f) {
      const std::size_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    f = std::move(finer);
  }
  TriangleMesh m;
  for (const Vec3& p : v) m.vertices.push_back(c + radius * p);
  m.triangles = f;
  return m;
}

/// The torus of major radius R and tube radius a about the z axis through c, nMajor x nMinor quads split in two.
inline TriangleMesh torusMesh(const Vec3& c, double R, double a, int nMajor, int nMinor) {
  TriangleMesh m;
  for (int i = 0; i < nMajor; ++i)
    for (int j = 0; j < nMinor; ++j) {
      const double phi = 2.0 * kPi * i / nMajor, theta = 2.0 * kPi * j / nMinor;
      const double rho = R + a * std::cos(theta);
      m.vertices.push_back(c + Vec3(rho * std::cos(phi), rho * std::sin(phi), a * std::sin(theta)));
    }
  const auto index = [&](int i, int j) { return std::size_t((i % nMajor) * nMinor + j % nMinor); };
  for (int i = 0; i < nMajor; ++i)
    for (int j = 0; j < nMinor; ++j) { // d/dphi x d/dtheta points outward
      m.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      m.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  return m;
}

/// The enclosed volume of an outward closed mesh (divergence theorem).
inline double meshVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  return v;
}

/// The winding number of a closed outward mesh about p: the sum of the faces' solid angles over 4 pi (Van
/// Oosterom & Strackee 1983), 1 inside and 0 outside, however rows and faces happen to line up.
inline double windingNumber(const TriangleMesh& m, const Vec3& p) {
  double omega = 0.0;
  for (const auto& t : m.triangles) {
    const Vec3 a = m.vertices[t[0]] - p, b = m.vertices[t[1]] - p, c = m.vertices[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    omega += 2.0 * std::atan2(numerator, denominator);
  }
  return omega / (4.0 * kPi);
}

/// Whether p lies strictly inside every face plane of a convex outward mesh: its exact inside test.
inline bool insideConvex(const TriangleMesh& m, const Vec3& p) {
  for (const auto& t : m.triangles) {
    const Vec3& a = m.vertices[t[0]];
    if ((m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a).dot(p - a) >= 0.0) return false;
  }
  return true;
}

/// Every vertex coordinate rounded to float: binary STL stores floats, and the five files must hold one surface.
inline TriangleMesh roundedToFloat(TriangleMesh m) {
  for (Vec3& p : m.vertices)
    for (int d = 0; d < 3; ++d) p[d] = static_cast<double>(static_cast<float>(p[d]));
  return m;
}

/// Writers of the five formats; decimal coordinates with 17 digits read back as the same double.
inline void writeAsciiStl(const std::filesystem::path& path, const TriangleMesh& m) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid test\n";
  for (const auto& t : m.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (std::size_t v : t)
      out << "   vertex " << m.vertices[v].x() << ' ' << m.vertices[v].y() << ' ' << m.vertices[v].z() << '\n';
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

inline void writeBinaryStl(const std::filesystem::path& path, const TriangleMesh& m) {
  std::ofstream out(path, std::ios::binary);
  const std::string header = "binary STL written by the PoroSPH geometry tests";
  char head[80] = {};
  std::memcpy(head, header.data(), header.size());
  out.write(head, 80);
  const std::uint32_t n = static_cast<std::uint32_t>(m.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4); // little-endian, as the format and x86 have it
  for (const auto& t : m.triangles) {
    float values[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) values[3 + 3 * k + d] = static_cast<float>(m.vertices[t[std::size_t(k)]][d]);
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

inline void writeObj(const std::filesystem::path& path, const TriangleMesh& m) {
  std::ofstream out(path);
  out.precision(17);
  for (const Vec3& p : m.vertices) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : m.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

inline void writeOff(const std::filesystem::path& path, const TriangleMesh& m) {
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << m.vertices.size() << ' ' << m.triangles.size() << " 0\n";
  for (const Vec3& p : m.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

inline void writePly(const std::filesystem::path& path, const TriangleMesh& m) {
  std::ofstream out(path);
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << m.vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : m.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

} // namespace poro::test
