// The footprint map (src/components/aurora/physics/footprint_map.h) built on the GPU from the curtains'
// polylines, the same map as the CPU's buildFootprintMap but in float: one pass per dispatch (uPass),
// ordered by storage barriers (src/components/aurora/footprint_map_gpu.h). Needs render/angle.glsl and
// components/aurora/footprint_map.glsl.
//
// A seed is a polyline point, numbered curtain · 65536 + point (the CPU's order: curtain, then point).
// Nearest means the smallest squared chord |a − b|² between the unit vectors (it grows with the angle,
// and unlike the dot product keeps its relative precision at small angles), ties to the smaller seed.
// The band's seed passes find it with two order-free atomic minima per texel: first the chord's bits
// (non-negative floats order as their bits), then among the seeds at exactly that chord the smallest
// number. The result does not depend on the order the GPU runs the seeds in, so every run gives the
// same bytes. Only the nearest seed's distance is computed as an angle.
layout(local_size_x = 64) in;

const int PASS_START = 0;          // per fine texel: centre directions (fine and coarse), buffers emptied
const int PASS_NEAREST_DISTANCE = 1; // per seed: band and coarse-seed distances
const int PASS_NEAREST_SEED = 2;     // per seed: the seeds at those distances
const int PASS_OTHER_DISTANCE = 3;   // per seed: nearest distance of another curtain than the nearest's
const int PASS_OTHER_SEED = 4;
const int PASS_FLOOD = 5;            // per coarse texel: one jump flooding step (Rong & Tan 2006)
const int PASS_COARSE_BOUND = 6;     // per coarse texel: the fine texels' lower bound there
const int PASS_ASSEMBLE = 7;         // per fine texel: the map's texel

const uint kNone = 0xFFFFFFFFu;

uniform int uPass;
uniform sampler2D uCurtainPolylines; // row c: unit vector, arclength km
uniform int uPointCount[MAX_CURTAINS];
uniform int uCurtainCount;
uniform int uPolylineWidth;          // texels per polyline row
uniform vec3 uCentre;
uniform vec3 uEast;
uniform float uAngularRadius;
uniform int uSize;                   // fine map side N
uniform int uCoarseSize;             // coarse map side
uniform float uPlanetRadiusKm;
uniform float uBandKm;               // the band's radius: exactWithinKm
uniform float uBandChord2;           // the same as a squared chord: (2 sin(band / 2R))²
uniform int uBandBox;                // texels each way around a seed's own that can lie in its band
uniform int uJumpStep;               // PASS_FLOOD's offset in coarse texels
uniform float uCoarseSlackKm;        // footprintCoarseSlackKm
uniform float uNoCurtainKm;          // the distance stored without curtains

layout(std430, binding = 0) buffer FineDirections { vec4 fineDirection[]; };
layout(std430, binding = 1) buffer CoarseDirections { vec4 coarseDirection[]; };
// Per fine texel: nearest squared chord's bits, nearest seed, other curtain's chord bits, its seed.
layout(std430, binding = 2) buffer Band { uint band[]; };
// Per coarse texel: the start's squared chord bits, then (PASS_COARSE_BOUND) the bound's bits in km.
layout(std430, binding = 3) buffer CoarseDistances { uint coarseDistance[]; };
layout(std430, binding = 4) readonly buffer FloodIn { uint floodIn[]; }; // seed per coarse texel
layout(std430, binding = 5) buffer FloodOut { uint floodOut[]; };
layout(rgba32f, binding = 0) writeonly uniform image2D uMap;

vec3 seedDirection(uint seed)
{
    return texelFetch(uCurtainPolylines, ivec2(int(seed & 0xFFFFu), int(seed >> 16)), 0).xyz;
}

float distanceKm(vec3 a, vec3 b) { return uPlanetRadiusKm * angleBetween(a, b); }

float chord2(vec3 a, vec3 b)
{
    vec3 d = a - b;
    return dot(d, d);
}

ivec2 texelOf(vec3 direction, int size)
{
    return ivec2(footprintMapTexel(footprintMapCoord(direction, uCentre, uEast, uAngularRadius), float(size)));
}

vec3 texelCentreDirection(int index, int size)
{
    vec2 coord = (vec2(index % size, index / size) + 0.5) / float(size);
    return footprintMapDirection(coord, uCentre, uEast, uAngularRadius);
}

// PASS_NEAREST_* and PASS_OTHER_*: seed `seed` at `direction` offered to the texels of its band box and
// (the nearest passes) to the 3x3 coarse texels around its own, JFA's start.
void offerSeed(uint seed, vec3 direction)
{
    ivec2 own = texelOf(direction, uSize);
    for (int j = max(own.y - uBandBox, 0); j <= min(own.y + uBandBox, uSize - 1); ++j)
        for (int i = max(own.x - uBandBox, 0); i <= min(own.x + uBandBox, uSize - 1); ++i) {
            int t = j * uSize + i;
            float d = chord2(fineDirection[t].xyz, direction);
            if (!(d <= uBandChord2))
                continue;
            uint bits = floatBitsToUint(d);
            if (uPass == PASS_NEAREST_DISTANCE)
                atomicMin(band[4 * t], bits);
            else if (uPass == PASS_NEAREST_SEED && bits == band[4 * t])
                atomicMin(band[4 * t + 1], seed);
            else if (uPass >= PASS_OTHER_DISTANCE && band[4 * t + 1] >> 16 != seed >> 16) {
                if (uPass == PASS_OTHER_DISTANCE)
                    atomicMin(band[4 * t + 2], bits);
                else if (bits == band[4 * t + 2])
                    atomicMin(band[4 * t + 3], seed);
            }
        }
    if (uPass >= PASS_OTHER_DISTANCE)
        return;
    ivec2 coarse = texelOf(direction, uCoarseSize);
    for (int j = max(coarse.y - 1, 0); j <= min(coarse.y + 1, uCoarseSize - 1); ++j)
        for (int i = max(coarse.x - 1, 0); i <= min(coarse.x + 1, uCoarseSize - 1); ++i) {
            int t = j * uCoarseSize + i;
            uint bits = floatBitsToUint(chord2(coarseDirection[t].xyz, direction));
            if (uPass == PASS_NEAREST_DISTANCE)
                atomicMin(coarseDistance[t], bits);
            else if (bits == coarseDistance[t])
                atomicMin(floodOut[t], seed);
        }
}

// PASS_FLOOD: texel t keeps, of its own seed and those of the 8 texels uJumpStep away, the nearest.
void flood(int t)
{
    ivec2 here = ivec2(t % uCoarseSize, t / uCoarseSize);
    vec3 centre = coarseDirection[t].xyz;
    uint best = kNone;
    float bestChord2 = 0.0;
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            ivec2 other = here + uJumpStep * ivec2(di, dj);
            if (any(lessThan(other, ivec2(0))) || any(greaterThanEqual(other, ivec2(uCoarseSize))))
                continue;
            uint seed = floodIn[other.y * uCoarseSize + other.x];
            if (seed == kNone)
                continue;
            float d = chord2(centre, seedDirection(seed));
            if (best == kNone || d < bestChord2 || (d == bestChord2 && seed < best)) {
                best = seed;
                bestChord2 = d;
            }
        }
    floodOut[t] = best;
}

// PASS_COARSE_BOUND: the distance from the coarse texel's centre to its flooded seed, less the slack
// (footprintCoarseSlackKm), and at least the band's radius.
void coarseBound(int t)
{
    float km = distanceKm(coarseDirection[t].xyz, seedDirection(floodIn[t])) - uCoarseSlackKm;
    coarseDistance[t] = floatBitsToUint(max(uBandKm, km));
}

// PASS_ASSEMBLE: texel (curtain, point, distance km, other curtain's seed or −1) as the CPU's build.
void assemble(int t)
{
    ivec2 texel = ivec2(t % uSize, t / uSize);
    vec4 value = vec4(-1.0, -1.0, uNoCurtainKm, -1.0);
    if (uCurtainCount > 0) {
        uint seed = band[4 * t + 1];
        float km;
        uint other = kNone;
        if (seed != kNone) {
            km = distanceKm(fineDirection[t].xyz, seedDirection(seed));
            other = band[4 * t + 3];
        } else {
            int k = uSize / uCoarseSize;
            int c = (texel.y / k) * uCoarseSize + texel.x / k;
            seed = floodIn[c];
            km = uintBitsToFloat(coarseDistance[c]);
        }
        value = vec4(float(seed >> 16), float(seed & 0xFFFFu), km, other == kNone ? -1.0 : float(other));
    }
    imageStore(uMap, texel, value);
}

void main()
{
    int index = int(DISPATCH_INVOCATION.x);
    if (uPass == PASS_START) {
        if (index >= uSize * uSize)
            return;
        fineDirection[index] = vec4(texelCentreDirection(index, uSize), 0.0);
        band[4 * index] = band[4 * index + 1] = band[4 * index + 2] = band[4 * index + 3] = kNone;
        if (index < uCoarseSize * uCoarseSize) {
            coarseDirection[index] = vec4(texelCentreDirection(index, uCoarseSize), 0.0);
            coarseDistance[index] = kNone;
            floodOut[index] = kNone;
        }
    } else if (uPass <= PASS_OTHER_SEED) {
        int curtain = index / uPolylineWidth, point = index % uPolylineWidth;
        if (curtain < uCurtainCount && point < uPointCount[curtain]) {
            uint seed = uint(curtain) << 16 | uint(point);
            offerSeed(seed, seedDirection(seed));
        }
    } else if (uPass == PASS_FLOOD) {
        if (index < uCoarseSize * uCoarseSize)
            flood(index);
    } else if (uPass == PASS_COARSE_BOUND) {
        if (index < uCoarseSize * uCoarseSize)
            coarseBound(index);
    } else if (index < uSize * uSize) {
        assemble(index);
    }
}
