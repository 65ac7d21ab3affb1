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
// No atomics and no sums across invocations: the same input gives the same bits.
layout(local_size_x = 64) in;

layout(std430, binding = 2) readonly buffer ChargeQuanta { int chargeQuanta[]; };
layout(std430, binding = 3) buffer PotentialIn { float potentialIn[]; };   // V
layout(std430, binding = 5) buffer Source { float source[]; };             // ρ̃/ε₀, V/m²
layout(std430, binding = 6) buffer PotentialOut { float potentialOut[]; }; // V

uniform vec3 uCells;         // cells per axis (1 beyond the dimension)
uniform vec3 uSpacing;       // m (1 beyond the dimension)
uniform int uCount;          // nodes
uniform int uMeanWhole;      // ⌊S̄⌋
uniform float uMeanFraction; // S̄ − ⌊S̄⌋
uniform float uSourceScale;  // V/m² per 2^-b particle: −q_e w / (ΔV 2^b ε₀)
uniform int uColour;         // 0 or 1
uniform float uOverRelaxation; // ω

int nodeIndex(ivec3 node)
{
    ivec3 n = ivec3(uCells);
    ivec3 wrapped = ((node % n) + n) % n;
    return wrapped.x + n.x * (wrapped.y + n.y * wrapped.z);
}

// The Jacobi value of node `node`: the one that makes its row of the discrete equation hold.
float jacobiValue(ivec3 node, int id)
{
    float sum = source[id];
    float diagonal = 0.0;
    for (int d = 0; d < PLASMA_DIMENSION; ++d) {
        ivec3 axis = ivec3(d == 0 ? 1 : 0, d == 1 ? 1 : 0, d == 2 ? 1 : 0);
        float inverseSquare = 1.0 / (uSpacing[d] * uSpacing[d]);
        sum += (potentialIn[nodeIndex(node - axis)] + potentialIn[nodeIndex(node + axis)]) * inverseSquare;
        diagonal += 2.0 * inverseSquare;
    }
    return sum / diagonal;
}

void main()
{
    int id = int(gl_GlobalInvocationID.x);
    if (id >= uCount)
        return;
    ivec3 n = ivec3(uCells);
    ivec3 node = ivec3(id % n.x, (id / n.x) % n.y, id / (n.x * n.y));
#if POISSON_PASS == 1
    source[id] = (float(chargeQuanta[id] - uMeanWhole) - uMeanFraction) * uSourceScale;
#elif POISSON_PASS == 2
    potentialOut[id] = jacobiValue(node, id);
#else
    if (((node.x + node.y + node.z) & 1) != uColour)
        return;
    float current = potentialIn[id];
    potentialIn[id] = current + uOverRelaxation * (jacobiValue(node, id) - current);
#endif
}
