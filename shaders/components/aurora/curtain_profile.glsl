// The electron flux across and along a curtain, relative to its peak: from the frames of the curtain
// detail's provider (a simulation of its small-scale structure) when the scene lists one, else a smooth Gaussian.
// s: arclength along the curtain (km), u: signed distance across it (km), c: the curtain.
const int MAX_CURTAINS = 16;
// Per curtain: detail offset along the curtain (km, drift reduced on the CPU), detail phase
// (0 smooth ... 1 turbulent), lateral scale (simulation sigma / curtain sigma, or 1 / sigma), -.
uniform vec4 uCurtainDetail[MAX_CURTAINS];

// A ray sub-step's profile integrated in closed form over the coordinate it changes most in: across the
// curtain from u0 to u0 + du at one s (a step that crosses it), or along it from s0 to s0 + ds at one u
// (a step that runs along it). (∫ profile, ∫ (q − q0) profile, the profile's mean at both ends) over that
// coordinate q, in km, km² and 1.

#ifdef HAS_CURTAIN_DETAIL // a listed component provides the role "curtain detail" (its frames)
uniform sampler2DArray uFluxTables; // the running integrals of the frames' flux (1/km) across and along at the
                                    // cell centres, both tables in one texture
                                    // (src/components/roles/flux_columns.h)
uniform vec4 uFluxStrip;  // strip length km, strip width km, frame count, peak scale
uniform vec4 uFluxLayout; // cells along, cells across, column entries per layer, row entries per layer

// The frames vary along a curtain: a ray step that runs along one is integrated along in closed form,
// with sub-steps that resolve the change across (fluxCellAcrossKm).
const bool kProfileVariesAlong = true;

// One of the two tables: its entries run over q (across for the columns, along for the rows), each holds
// the cells of the other axis p.
struct FluxTable {
    float cellKm;     // cell width along q, simulation km
    float originKm;   // q at the start of the strip
    float entries;    // cells along q + 1
    float cells;      // cells along p (each entry's strip holds them and two ghosts)
    float tiles;      // entries per layer
    float firstLayer;
};

FluxTable fluxTable(bool along)
{
    float nx = uFluxLayout.x, ny = uFluxLayout.y;
    float columnLayers = ceil((ny + 1.0) / uFluxLayout.z);
    if (along)
        return FluxTable(uFluxStrip.x / nx, 0.0, nx + 1.0, ny, uFluxLayout.w, columnLayers);
    return FluxTable(uFluxStrip.y / ny, -0.5 * uFluxStrip.y, ny + 1.0, nx, uFluxLayout.z, 0.0);
}

// The running integrals (of F and q F from the strip's start, flux_column.glsl, fluxColumnValue) at q,
// within the strip, and the flux F there, of the entries at p (cells, 0 at the first cell's centre,
// -1/2 ≤ p ≤ cells − 1/2) and frame coordinate frameY: the texture filters along p and between frames;
// along q, the entry at the centre below q is extended in float.
vec3 fluxTableAt(FluxTable t, float p, float frameY, float q)
{
    float below = clamp(floor((q - t.originKm) / t.cellKm - 0.5), -1.0, t.entries - 2.0);
    float entry = below + 1.0;
    float tile = floor(entry / t.tiles);
    float x = (entry - tile * t.tiles) * (t.cells + 2.0) + p + 1.5; // the ghost texel, then cell p
    float width = max(uFluxLayout.x, uFluxLayout.y) + 2.0;
    vec4 texel = textureLod(uFluxTables, vec3(x / width, frameY, t.firstLayer + tile), 0.0);
    COUNT_WORK(w, 1);
    float centre = t.originKm + (below + 0.5) * t.cellKm;
    return vec3(fluxColumnValue(texel, centre, q - centre, t.cellKm), texel.z + texel.w * (q - centre) / t.cellKm);
}

// The closed-form integral over a sub-step: across (along = false) from u0 = q0 to u0 + dq at s = fixedKm,
// or along (along = true) from s0 = q0 to s0 + dq at u = fixedKm (km, dq either sign); see above. Both
// read the texture through the same two fetches (a third where a step along leaves the strip's period).
vec3 curtainIntegral(int c, bool along, float fixedKm, float q0, float dq)
{
    vec4 detail = uCurtainDetail[c];
    FluxTable t = fluxTable(along);
    float frameY = (detail.y * (uFluxStrip.z - 1.0) + 0.5) / uFluxStrip.z;
    float halfWidth = 0.5 * uFluxStrip.y;
    float stripKm = uFluxStrip.x;
    // Across (simulation km) where the step runs along, and the ends of q: along, from s0 reduced into the
    // strip (periodic); across, in simulation km.
    float a = fixedKm * detail.z;
    float qa = along ? mod(q0 + detail.x, stripKm) : q0 * detail.z;
    float qb = along ? qa + dq : (q0 + dq) * detail.z;
    // p: the fixed coordinate in the entries' cells; along, periodic; across, beyond the strip no flux.
    float p = along ? (a + halfWidth) / (uFluxStrip.y / uFluxLayout.y) - 0.5
                    : mod((fixedKm + detail.x) / (stripKm / uFluxLayout.x), uFluxLayout.x) - 0.5;
    // Along, the end may lie in the next or previous period, where the integrals continue by the
    // period's: x = kL + y gives A = A(y) + k A(L), B = B(y) + k B(L) + L (k(k − 1)/2 A(L) + k A(y)).
    float k = along ? floor(qb / stripKm) : 0.0;
    float qaRead = along ? qa : clamp(qa, -halfWidth, halfWidth);
    float qbRead = along ? qb - k * stripKm : clamp(qb, -halfWidth, halfWidth);
    vec3 lo = fluxTableAt(t, p, frameY, qaRead);
    vec3 hi = fluxTableAt(t, p, frameY, qbRead);
    if (k != 0.0) {
        vec3 period = fluxTableAt(t, p, frameY, stripKm);
        hi.y += k * period.y + stripKm * (0.5 * k * (k - 1.0) * period.x + k * hi.x);
        hi.x += k * period.x;
    }
    if (along && abs(a) >= halfWidth)
        return vec3(0.0);
    if (!along) {
        lo.z = abs(qa) < halfWidth ? lo.z : 0.0;
        hi.z = abs(qb) < halfWidth ? hi.z : 0.0;
    }
    float scale = along ? 1.0 : detail.z; // simulation km per curtain km along q
    float mass = (hi.x - lo.x) / scale;
    float start = along ? qa : q0;        // q's start in the units of the moment: strip km, or curtain km
    return uFluxStrip.w * vec3(mass, (hi.y - lo.y) / (scale * scale) - start * mass, 0.5 * (lo.z + hi.z));
}

// The width across curtain c (km) over which its flux is resolved: the frames' cell across, scaled to it.
float fluxCellAcrossKm(int c)
{
    return uFluxStrip.y / uFluxLayout.y / uCurtainDetail[c].z;
}

// The length along the curtain over which its flux is resolved (km): the frames' cell along (the
// texture interpolates linearly between cells).
float fluxCellAlongKm()
{
    return uFluxStrip.x / uFluxLayout.x;
}
#else
// The smooth Gaussian does not change along a curtain: the column across is exact for any sub-step.
const bool kProfileVariesAlong = false;

// Across only (a profile constant along needs no other): the Gaussian exp(−a²/2), a = u / σ, in closed form.
vec3 curtainIntegral(int c, bool along, float fixedKm, float q0, float dq)
{
    float scale = uCurtainDetail[c].z;
    float a0 = q0 * scale;
    float a1 = (q0 + dq) * scale;
    float mass = gaussianMass(a0, a1) / scale;
    return vec3(mass, gaussianMoment(a0, a1) / (scale * scale) - q0 * mass,
                0.5 * (exp(-0.5 * a0 * a0) + exp(-0.5 * a1 * a1)));
}

float fluxCellAcrossKm(int c)
{
    return 1.0e30;
}

// Unbounded: the smooth Gaussian does not change along the curtain.
float fluxCellAlongKm()
{
    return 1.0e30;
}
#endif
