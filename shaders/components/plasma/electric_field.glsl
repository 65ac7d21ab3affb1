// The electric field at a grid node from the potential, E = −∇φ, by the central difference along
// one axis (second order; Birdsall & Langdon 1991, §2-5). With the (2·dimension + 1)-point Laplacian
// of the Poisson solve and the same CIC weights for deposit and gather, the force on a particle
// from its own charge vanishes and total momentum is conserved (ibid. §8-5).
// potentialBelow, potentialAbove: φ (V) at the node's neighbours at −Δx and +Δx; spacing Δx (m).
real centralDifferenceField(real potentialBelow, real potentialAbove, real spacing)
{
    return (potentialBelow - potentialAbove) / (real(2.0) * spacing);
}
