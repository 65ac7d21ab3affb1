// Cloud-in-cell (CIC) weighting of a particle on a periodic grid (shared by the compute shaders
// and the C++ simulation, src/common/glsl.h). Birdsall & Langdon, "Plasma Physics via Computer
// Simulation" (1991), §2-6 and §14-2: each particle is a uniform cloud one cell wide, so its weight
// on the 2^dimension nodes of its cell is the product over the axes of the linear weights
// (1 − f) for the lower node and f for the upper one, f the particle's fraction of the cell.
// Depositing the charge and gathering the field with the same weights gives no self-force.
//
// gridCoordinate: the position in cells (x/Δx per axis; node i sits at i). Axes beyond `dimension`
// are ignored. corner: bit d set means the upper node along axis d.

// The particle's fraction of its cell along each axis, in [0, 1).
vec3 cicCellFraction(vec3 gridCoordinate)
{
    return gridCoordinate - floor(gridCoordinate);
}

// The weight of one corner of the particle's cell; the 2^dimension weights sum to 1.
real cicCornerWeight(vec3 fraction, int corner, int dimension)
{
    real weight = real(1.0);
    for (int d = 0; d < dimension; ++d)
        weight *= ((corner >> d) & 1) == 1 ? fraction[d] : real(1.0) - fraction[d];
    return weight;
}

// The charge density (C/m³) one particle of charge q (C) adds to a corner node whose cell has
// volume cellVolume (m³; the product of the spacings of the grid's axes).
real cicCornerChargeDensity(real charge, real cellVolume, vec3 fraction, int corner, int dimension)
{
    return charge / cellVolume * cicCornerWeight(fraction, corner, dimension);
}

// One corner's share of the field at the particle (V/m), from the field at that node.
vec3 cicCornerField(vec3 nodeField, vec3 fraction, int corner, int dimension)
{
    return cicCornerWeight(fraction, corner, dimension) * nodeField;
}
