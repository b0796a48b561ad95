// Test helper: small closed triangle meshes and their STL files: an axis-aligned box of 12
// triangles (outward), a UV sphere (poles, rings of equal latitude; convex, its vertices
// rounded to float as a binary STL stores them), written as ASCII or binary STL.
#pragma once
#include "core/types.hpp"
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

namespace shizuku::test {

struct Mesh {
  std::vector<Vec<3>> v;
  std::vector<std::array<int, 3>> t;
};

// Vertex i = x + 2y + 4z of the box; each face a quad, counter-clockwise seen from outside.
inline Mesh boxMesh(const Vec<3>& lo, const Vec<3>& hi) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.v.push_back(Vec<3>(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]));
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.t.push_back({q[0], q[1], q[2]});
    m.t.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// Poles on the z axis, `rings` rings of `perRing` vertices between them.
inline Mesh uvSphere(const Vec<3>& centre, double radius, int rings, int perRing) {
  Mesh m;
  auto rounded = [](const Vec<3>& x) {
    Vec<3> r;
    for (int k = 0; k < 3; ++k) {
      volatile float f = static_cast<float>(x[k]);  // (g++ 12 -O3 dropped a plain round trip)
      r[k] = f;
    }
    return r;
  };
  m.v.push_back(rounded(centre + Vec<3>(0, 0, radius)));
  for (int r = 1; r <= rings; ++r) {
    const double theta = M_PI * r / (rings + 1);
    for (int j = 0; j < perRing; ++j) {
      const double phi = 2 * M_PI * j / perRing;
      m.v.push_back(rounded(centre + radius * Vec<3>(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                     std::cos(theta))));
    }
  }
  m.v.push_back(rounded(centre - Vec<3>(0, 0, radius)));
  const int south = int(m.v.size()) - 1;
  auto at = [&](int r, int j) { return 1 + (r - 1) * perRing + (j % perRing); };
  for (int j = 0; j < perRing; ++j) {
    m.t.push_back({0, at(1, j), at(1, j + 1)});
    m.t.push_back({south, at(rings, j + 1), at(rings, j)});
    for (int r = 1; r < rings; ++r) {
      m.t.push_back({at(r, j), at(r + 1, j), at(r + 1, j + 1)});
      m.t.push_back({at(r, j), at(r + 1, j + 1), at(r, j + 1)});
    }
  }
  return m;
}

inline Vec<3> normalOf(const Mesh& m, const std::array<int, 3>& t) {
  const Vec<3> n = (m.v[t[1]] - m.v[t[0]]).cross(m.v[t[2]] - m.v[t[0]]);
  return n.norm() > 0 ? Vec<3>(n / n.norm()) : n;
}

inline void writeAsciiStl(const std::string& path, const Mesh& m) {
  std::ofstream f(path);
  f << std::setprecision(9) << "solid test\n";
  for (const auto& t : m.t) {
    const Vec<3> n = normalOf(m, t);
    f << " facet normal " << n[0] << " " << n[1] << " " << n[2] << "\n  outer loop\n";
    for (int i : t) f << "   vertex " << m.v[i][0] << " " << m.v[i][1] << " " << m.v[i][2] << "\n";
    f << "  endloop\n endfacet\n";
  }
  f << "endsolid test\n";
}

inline void writeBinaryStl(const std::string& path, const Mesh& m) {
  std::ofstream f(path, std::ios::binary);
  std::string header = "binary STL of a Shizuku test";
  header.resize(80, ' ');
  f.write(header.data(), 80);
  const std::uint32_t n = std::uint32_t(m.t.size());
  f.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.t) {
    float values[12];
    const Vec<3> normal = normalOf(m, t);
    for (int k = 0; k < 3; ++k) values[k] = float(normal[k]);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) values[3 + 3 * i + k] = float(m.v[t[i]][k]);
    f.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = 0;
    f.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

}  // namespace shizuku::test
