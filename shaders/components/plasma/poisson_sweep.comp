// Poisson's equation ∇²φ = −ρ/ε₀ on the periodic grid, in float, on the (2·dimension + 1)-point
// Laplacian of the CPU solvers (Birdsall & Langdon 1991, §2-5). The same text for 1D, 2D and 3D:
// PLASMA_DIMENSION (1–3) and one pass per program, POISSON_PASS, one invocation per node:
//   1 source: s = ρ̃/ε₀ (V/m²) from the deposit's fixed-point node sums S (in 2^-b particles),
//     ρ̃ ∝ S − S̄ with the mean S̄ = uMeanWhole + uMeanFraction split so that the integer part
//     subtracts exactly.
//   2 Jacobi: φ'[i] = (Σ_d (φ[i+d] + φ[i−d])/Δ_d² + s[i]) / Σ_d 2/Δ_d², from potentialIn into
//     potentialOut (every node reads only the previous sweep: the order of the invocations does not
//     matter).
//   3 red-black SOR half-sweep: the nodes of colour uColour ((i + j + k) mod 2) take
//     φ ← φ + ω (φ_GS − φ), φ_GS the Jacobi value above; a node of one colour reads only nodes of
//     the other (every cell count even), so each half-sweep is order-independent and in place.
//   4 residual: r = s + ∇²φ (V/m², so that ∇²e = −r for the error e), into potentialOut.
//   5 restriction by full weighting, one invocation per coarse node: the coarse source is the fine
//     residual (read from potentialOut) at the nodes 2c + o, o ∈ {−1, 0, 1}^d, weighted Π_d (1/2 for
//     o_d = 0, 1/4 otherwise) (Trottenberg, Oosterlee & Schüller 2001, "Multigrid", §2.3); the coarse
//     correction (potentialIn) starts at 0. Zeroing it here, in a shader, keeps it in the order of
//     the dispatches: a buffer update from the CPU is not ordered after earlier shader accesses
//     without GL_BUFFER_UPDATE_BARRIER_BIT, and on NVIDIA it overtook the previous V-cycle's.
//   6 prolongation, one invocation per fine node: φ += the coarse correction (coarsePotential)
//     interpolated linearly along each axis (ibid.).
// Passes 4–6 make a geometric multigrid V-cycle with pass 3 at ω = 1 (red-black Gauss–Seidel) as
// the smoother. No atomics and no sums across invocations: the same input gives the same bits.
layout(local_size_x = 64) in;

layout(std430, binding = 2) readonly buffer ChargeQuanta { int chargeQuanta[]; };
layout(std430, binding = 3) buffer PotentialIn { float potentialIn[]; };   // V
layout(std430, binding = 5) buffer Source { float source[]; };             // ρ̃/ε₀, V/m²
layout(std430, binding = 6) buffer PotentialOut { float potentialOut[]; }; // V, or the residual
layout(std430, binding = 7) readonly buffer CoarsePotential { float coarsePotential[]; }; // V

uniform vec3 uCells;         // cells per axis (1 beyond the dimension)
uniform vec3 uSpacing;       // m (1 beyond the dimension)
uniform int uCount;          // nodes
uniform int uMeanWhole;      // ⌊S̄⌋
uniform float uMeanFraction; // S̄ − ⌊S̄⌋
uniform float uSourceScale;  // V/m² per 2^-b particle: −q_e w / (ΔV 2^b ε₀)
uniform int uColour;         // 0 or 1
uniform float uOverRelaxation; // ω
uniform vec3 uOtherCells;      // the fine grid's cells (pass 5) or the coarse grid's (pass 6)

// The index of a node on the periodic grid with n cells per axis, for −n ≤ node < 2n (GLSL leaves %
// of a negative operand undefined, so n is added first).
int nodeIndexOn(ivec3 node, ivec3 n)
{
    ivec3 wrapped = (node + n) % n;
    return wrapped.x + n.x * (wrapped.y + n.y * wrapped.z);
}

int nodeIndex(ivec3 node)
{
    return nodeIndexOn(node, ivec3(uCells));
}

ivec3 axisStep(int d)
{
    return ivec3(d == 0 ? 1 : 0, d == 1 ? 1 : 0, d == 2 ? 1 : 0);
}

// The Jacobi value of node `node`: the one that makes its row of the discrete equation hold.
float jacobiValue(ivec3 node, int id)
{
    float sum = source[id];
    float diagonal = 0.0;
    for (int d = 0; d < PLASMA_DIMENSION; ++d) {
        ivec3 axis = axisStep(d);
        float inverseSquare = 1.0 / (uSpacing[d] * uSpacing[d]);
        sum += (potentialIn[nodeIndex(node - axis)] + potentialIn[nodeIndex(node + axis)]) * inverseSquare;
        diagonal += 2.0 * inverseSquare;
    }
    return sum / diagonal;
}

void main()
{
    int id = int(DISPATCH_INVOCATION.x);
    if (id >= uCount)
        return;
    ivec3 n = ivec3(uCells);
    ivec3 node = ivec3(id % n.x, (id / n.x) % n.y, id / (n.x * n.y));
#if POISSON_PASS == 1
    source[id] = (float(chargeQuanta[id] - uMeanWhole) - uMeanFraction) * uSourceScale;
#elif POISSON_PASS == 2
    potentialOut[id] = jacobiValue(node, id);
#elif POISSON_PASS == 4
    float laplacian = 0.0;
    for (int d = 0; d < PLASMA_DIMENSION; ++d)
        laplacian += (potentialIn[nodeIndex(node - axisStep(d))] - 2.0 * potentialIn[id] +
                      potentialIn[nodeIndex(node + axisStep(d))]) / (uSpacing[d] * uSpacing[d]);
    potentialOut[id] = source[id] + laplacian;
#elif POISSON_PASS == 5
    ivec3 fine = ivec3(uOtherCells);
    float sum = 0.0;
    for (int offset = 0; offset < 27; ++offset) {
        ivec3 o = ivec3(offset % 3, (offset / 3) % 3, offset / 9) - 1;
        float weight = 1.0;
        bool inside = true;
        for (int d = 0; d < 3; ++d) {
            if (d >= PLASMA_DIMENSION)
                inside = inside && o[d] == 0;
            else
                weight *= o[d] == 0 ? 0.5 : 0.25;
        }
        if (inside)
            sum += weight * potentialOut[nodeIndexOn(2 * node + o, fine)];
    }
    source[id] = sum;
    potentialIn[id] = 0.0;
#elif POISSON_PASS == 6
    ivec3 coarse = ivec3(uOtherCells);
    ivec3 base = node / 2;
    ivec3 odd = node & 1;
    float correction = 0.0;
    for (int corner = 0; corner < (1 << PLASMA_DIMENSION); ++corner) {
        ivec3 bit = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        if (any(greaterThan(bit, odd)))
            continue;
        float weight = 1.0;
        for (int d = 0; d < PLASMA_DIMENSION; ++d)
            weight *= odd[d] == 1 ? 0.5 : 1.0;
        correction += weight * coarsePotential[nodeIndexOn(base + bit, coarse)];
    }
    potentialIn[id] += correction;
#else
    if (((node.x + node.y + node.z) & 1) != uColour)
        return;
    float current = potentialIn[id];
    potentialIn[id] = current + uOverRelaxation * (jacobiValue(node, id) - current);
#endif
}
