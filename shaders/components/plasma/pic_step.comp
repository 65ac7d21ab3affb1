// One electrostatic particle-in-cell step on the GPU, in float, with the shared kernels
// (cloud_in_cell.glsl, electric_field.glsl, boris_push.glsl, assembled before this text). The same
// text for 1D, 2D and 3D: PLASMA_DIMENSION (1–3) and one pass per program, PLASMA_PASS:
//   1 deposit: one invocation per particle; the CIC weights of its 2^d corners in fixed point, each
//     rounded to a multiple of 2^-uQuantumBits, the last corner taking the rest so that every
//     particle adds exactly 2^uQuantumBits; integer atomics make the node sums independent of the
//     invocations' order (float atomics would not be: rounding depends on the order of the adds).
//   2 field: one invocation per node, E = −∇φ by central differences.
//   3 gather and push: one invocation per particle, E at the particle by the same CIC weights plus
//     uExternalField, the Boris velocity, and (uMovePositions 1) the leapfrog position.
// Positions in metres inside the box, velocities in m/s, fields in V/m, the potential in V.
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) buffer Velocities { vec4 velocities[]; };
layout(std430, binding = 2) buffer ChargeQuanta { int chargeQuanta[]; }; // per node, in 2^-uQuantumBits particles
layout(std430, binding = 3) readonly buffer Potential { float potential[]; };
layout(std430, binding = 4) buffer NodeField { vec4 nodeField[]; };

uniform vec3 uCells;   // cells per axis (1 beyond the dimension)
uniform vec3 uSpacing; // m (1 beyond the dimension)
uniform int uCount;    // particles, or nodes in pass 2
uniform int uQuantumBits;
uniform vec3 uExternalField;  // V/m
uniform vec3 uMagneticField;  // T
uniform float uChargeOverMass; // C/kg
uniform float uDt;             // s
uniform int uMovePositions;

// The node (i, j, k) of PeriodicGrid::index: wrapped into the box, x fastest. Every node asked for
// lies within one box of it (−n ≤ node < 2n), and n is added before % because GLSL leaves % of a
// negative operand undefined.
int nodeIndex(ivec3 node)
{
    ivec3 n = ivec3(uCells);
    ivec3 wrapped = (node + n) % n;
    return wrapped.x + n.x * (wrapped.y + n.y * wrapped.z);
}

ivec3 cornerNode(ivec3 lower, int corner)
{
    return lower + ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
}

const int kCorners = 1 << PLASMA_DIMENSION;

void main()
{
    int id = int(DISPATCH_INVOCATION.x);
    if (id >= uCount)
        return;
#if PLASMA_PASS == 2
    ivec3 n = ivec3(uCells);
    ivec3 node = ivec3(id % n.x, (id / n.x) % n.y, id / (n.x * n.y));
    vec3 field = vec3(0.0);
    for (int d = 0; d < PLASMA_DIMENSION; ++d) {
        ivec3 axis = ivec3(d == 0 ? 1 : 0, d == 1 ? 1 : 0, d == 2 ? 1 : 0);
        field[d] = centralDifferenceField(potential[nodeIndex(node - axis)], potential[nodeIndex(node + axis)],
                                          uSpacing[d]);
    }
    nodeField[id] = vec4(field, 0.0);
#else
    vec3 gridCoordinate = positions[id].xyz / uSpacing;
    ivec3 lower = ivec3(floor(gridCoordinate));
    vec3 fraction = cicCellFraction(gridCoordinate);
#if PLASMA_PASS == 1
    int whole = 1 << uQuantumBits;
    int rest = whole;
    for (int corner = 0; corner < kCorners - 1; ++corner) {
        int quanta = int(round(cicCornerWeight(fraction, corner, PLASMA_DIMENSION) * float(whole)));
        atomicAdd(chargeQuanta[nodeIndex(cornerNode(lower, corner))], quanta);
        rest -= quanta;
    }
    atomicAdd(chargeQuanta[nodeIndex(cornerNode(lower, kCorners - 1))], rest);
#else
    vec3 field = uExternalField;
    for (int corner = 0; corner < kCorners; ++corner)
        field += cicCornerField(nodeField[nodeIndex(cornerNode(lower, corner))].xyz, fraction, corner, PLASMA_DIMENSION);
    vec3 velocity = borisVelocity(velocities[id].xyz, field, uMagneticField, uChargeOverMass, uDt);
    velocities[id] = vec4(velocity, 0.0);
    if (uMovePositions == 1)
        positions[id] = vec4(leapfrogPosition(positions[id].xyz, velocity, uDt, uCells * uSpacing), 0.0);
#endif
#endif
}
