#pragma once
// The particle–mesh coupling: charge onto the grid, the field from the potential, the field back at
// the particles, with the shared kernels of shaders/components/plasma (cloud_in_cell.glsl,
// triangular_shaped_cloud.glsl, electric_field.glsl) compiled in double.
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <glm/vec3.hpp>

#include <vector>

namespace aurorawall::components::plasma::simulation {

// The particle's shape, i.e. its weights on the nodes (the same for the deposit and the gather):
// cloud-in-cell, linear, on the 2^d corners of its cell; or the triangular-shaped cloud, the
// quadratic spline, on the 3^d nodes nearest to it (less aliasing and noise, more nodes).
enum class ParticleShape { CloudInCell, TriangularShapedCloud };

// The charge density (C/m³) at every node: the electrons' deposit with the given shape plus the
// uniform neutralising ion background, i.e. minus the deposit's mean, so Σρ = 0 (to rounding).
// Deterministic: the deposits are added in a fixed order, particle by particle in index order and,
// for each, its nodes in increasing number (CIC: bit d set for the upper node along axis d; TSC:
// base-3 digit d for the step −1, 0, 1 along axis d), so the same particles give the same bits.
std::vector<double> depositChargeDensity(const PeriodicGrid& grid, const Particles& electrons,
                                         ParticleShape shape = ParticleShape::CloudInCell);

// The same deposit at the cell centres: the electrons moved back by half a cell along every axis of
// the grid's dimension before depositing, so node (i, j, k) stands for the point ((i + ½)Δx, …).
// The electron density there is the mean density minus this over the elementary charge.
std::vector<double> depositChargeDensityAtCellCentres(const PeriodicGrid& grid, const Particles& electrons);

// E = −∇φ (V/m) at every node by central differences; zero along the axes beyond the grid's dimension.
std::vector<glm::dvec3> nodeElectricField(const PeriodicGrid& grid, const std::vector<double>& potential);

// The field (V/m) at each position, interpolated from the nodes with the deposit's weights.
std::vector<glm::dvec3> gatherField(const PeriodicGrid& grid, const std::vector<glm::dvec3>& nodeField,
                                    const std::vector<glm::dvec3>& positions,
                                    ParticleShape shape = ParticleShape::CloudInCell);

} // namespace aurorawall::components::plasma::simulation
