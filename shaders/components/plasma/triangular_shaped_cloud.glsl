// Triangular-shaped-cloud (TSC) weighting of a particle on a periodic grid (shared by the C++
// simulation through src/common/glsl.h). Birdsall & Langdon, "Plasma Physics via Computer
// Simulation" (1991), ch. 8: the quadratic spline (three cell-wide boxes convolved) spreads the
// particle over the 3 nodes nearest to it along each axis; with δ = x/Δx − i the offset from the
// nearest node i (|δ| ≤ ½) the weights are
//   W(i − 1) = ½(½ − δ)²,  W(i) = ¾ − δ²,  W(i + 1) = ½(½ + δ)².
// They sum to 1, their mean is the particle's position and their variance about it Δx²/4 for any δ.
// Its shape factor S(k) = (sin(kΔx/2)/(kΔx/2))³ against cloud-in-cell's square falls faster past
// the grid's Nyquist wave, so less aliasing. Depositing the charge and gathering the field with the
// same weights gives no self-force.
//
// gridCoordinate: the position in cells (x/Δx per axis; node i sits at i). Axes beyond `dimension`
// are ignored. node: 0 … 3^dimension − 1, its base-3 digit along axis d being 0, 1, 2 for the
// nodes i − 1, i, i + 1 along that axis.

// The node nearest to the particle along each axis (the upper one at exactly half a cell).
vec3 tscNearestNode(vec3 gridCoordinate)
{
    vec3 fraction = gridCoordinate - floor(gridCoordinate);
    return floor(gridCoordinate) + step(vec3(0.5), fraction);
}

// The particle's offset from its nearest node along each axis, in cells, in [−½, ½). Computed from
// the fraction of the cell so it is exact: f − 1 for f ≥ ½ has no rounding (Sterbenz).
vec3 tscNodeOffset(vec3 gridCoordinate)
{
    vec3 fraction = gridCoordinate - floor(gridCoordinate);
    return fraction - step(vec3(0.5), fraction);
}

// The step (−1, 0 or 1) along axis `axis` from the nearest node to the node numbered `node`.
int tscNodeStep(int node, int axis)
{
    int place = 1;
    for (int d = 0; d < axis; ++d)
        place *= 3;
    return (node / place) % 3 - 1;
}

// The quadratic spline's weight on the node `nodeStep` (−1, 0 or 1) from the nearest one, for the
// particle's offset δ from the nearest node.
real tscAxisWeight(real offset, int nodeStep)
{
    if (nodeStep == 0)
        return real(0.75) - offset * offset;
    real side = real(0.5) + real(nodeStep) * offset;
    return real(0.5) * side * side;
}

// The weight of one of the 3^dimension nodes; the weights sum to 1.
real tscNodeWeight(vec3 offset, int node, int dimension)
{
    real weight = real(1.0);
    for (int d = 0; d < dimension; ++d)
        weight *= tscAxisWeight(offset[d], tscNodeStep(node, d));
    return weight;
}

// The charge density (C/m³) one particle of charge q (C) adds to a node, cellVolume (m³) the product
// of the grid's spacings.
real tscNodeChargeDensity(real charge, real cellVolume, vec3 offset, int node, int dimension)
{
    return charge / cellVolume * tscNodeWeight(offset, node, dimension);
}

// One node's share of the field at the particle (V/m), from the field at that node.
vec3 tscNodeField(vec3 nodeField, vec3 offset, int node, int dimension)
{
    return tscNodeWeight(offset, node, dimension) * nodeField;
}
