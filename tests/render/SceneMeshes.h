#pragma once

// Meshes for render tests and the benchmark: a UV sphere and a flat grid, with iso-lines.

#include "phigs/traverse/DrawList.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>

namespace render_test {

/// A UV sphere (counter-clockwise seen from outside) with unit normals, uv and `isoLines` iso-lines
/// in each parameter direction.
inline std::shared_ptr<phigs::MeshData> sphere(glm::vec3 centre, float radius, int slices, int stacks,
                                               int isoLines = 0) {
    auto mesh = std::make_shared<phigs::MeshData>();
    for (int j = 0; j <= stacks; ++j)
        for (int i = 0; i <= slices; ++i) {
            const float u = float(i) / float(slices), v = float(j) / float(stacks);
            const float theta = 6.2831853f * u, phi = 3.14159265f * v;
            const glm::vec3 n(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                              std::cos(phi));
            mesh->positions.push_back(centre + radius * n);
            mesh->normals.push_back(n);
            mesh->uv.push_back({u, v});
        }
    const int row = slices + 1;
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            // v runs from the +z pole down, u around z: (a, c, b) is counter-clockwise from outside.
            mesh->triangles.insert(mesh->triangles.end(), {a, c, b, b, c, d});
        }
    for (int k = 1; k < isoLines; ++k) {
        std::vector<std::uint32_t> constantV, constantU;
        const int j = k * stacks / isoLines, i = k * slices / isoLines;
        for (int s = 0; s <= slices; ++s) constantV.push_back(j * row + s);
        for (int s = 0; s <= stacks; ++s) constantU.push_back(s * row + i);
        mesh->isoLines.push_back(constantV);
        mesh->isoLines.push_back(constantU);
    }
    return mesh;
}

/// A flat n x n grid over [x0,x1] x [y0,y1] at height z, normals +z.
inline std::shared_ptr<phigs::MeshData> grid(double x0, double y0, double x1, double y1, double z, int n) {
    auto mesh = std::make_shared<phigs::MeshData>();
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            mesh->positions.push_back(
                glm::vec3(float(x0 + (x1 - x0) * i / n), float(y0 + (y1 - y0) * j / n), float(z)));
            mesh->normals.push_back(glm::vec3(0, 0, 1));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            mesh->triangles.insert(mesh->triangles.end(), {a, b, d, a, d, c});
        }
    return mesh;
}

}  // namespace render_test
