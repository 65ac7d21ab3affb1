// The electron flux across and along a curtain, relative to its peak: from the frames of the curtain
// detail's provider (a simulation of its small-scale structure) when the scene lists one, else a smooth Gaussian.
// s: arclength along the curtain (km), u: signed distance across it (km), c: the curtain.
#define MAX_CURTAINS 16
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
    real cellKm;   // cell width along q, simulation km
    real originKm; // q at the start of the strip
    real entries;  // cells along q + 1
    real cells;    // cells along p (each entry's strip holds them and two ghosts)
    real tiles;    // entries per layer
    real firstLayer;
    real width;    // texels in a row of the texture
};

FluxTable fluxTable(bool along)
{
    real nx = uFluxLayout.x, ny = uFluxLayout.y;
    FluxTable t;
    t.cellKm = along ? uFluxStrip.x / nx : uFluxStrip.y / ny;
    t.originKm = along ? 0.0 : -0.5 * uFluxStrip.y;
    t.entries = (along ? nx : ny) + 1.0;
    t.cells = along ? ny : nx;
    t.tiles = along ? uFluxLayout.w : uFluxLayout.z;
    t.firstLayer = along ? ceil((ny + 1.0) / uFluxLayout.z) : 0.0; // the rows follow the columns' layers
    t.width = max(nx, ny) + 2.0;
    return t;
}

// The running integrals (of F and q F from the strip's start, flux_column.glsl, fluxColumnValue) at q,
// within the strip, and the flux F there, of the entries at p (cells, 0 at the first cell's centre,
// -1/2 ≤ p ≤ cells − 1/2) and frame coordinate frameY: the texture filters along p and between frames;
// along q, the entry at the centre below q is extended in float.
vec3 fluxTableAt(FluxTable t, real p, real frameY, real q)
{
    real below = clamp(floor((q - t.originKm) / t.cellKm - 0.5), -1.0, t.entries - 2.0);
    real entry = below + 1.0;
    real tile = floor(entry / t.tiles);
    real x = (entry - tile * t.tiles) * (t.cells + 2.0) + p + 1.5; // the ghost texel, then cell p
    vec4 texel = textureLod(uFluxTables, vec3(x / t.width, frameY, t.firstLayer + tile), 0.0);
    COUNT_WORK(w, 1);
    real centre = t.originKm + (below + 0.5) * t.cellKm;
    return vec3(fluxColumnValue(texel, centre, q - centre, t.cellKm), texel.z + texel.w * (q - centre) / t.cellKm);
}

// The texture's coordinate between the frames for curtain c's detail phase (the texture blends two frames).
real fluxFrameY(int c)
{
    return (uCurtainDetail[c].y * (uFluxStrip.z - 1.0) + 0.5) / uFluxStrip.z;
}

// The fixed coordinate p of curtainIntegralAt at fixedKm (km across when along, else along): in the
// entries' cells, 0 at the first cell's centre; along the strip reduced into its period.
real curtainFixedCell(int c, bool along, real fixedKm)
{
    vec4 detail = uCurtainDetail[c];
    return along ? (fixedKm * detail.z + 0.5 * uFluxStrip.y) / (uFluxStrip.y / uFluxLayout.y) - 0.5
                 : mod((fixedKm + detail.x) / (uFluxStrip.x / uFluxLayout.x), uFluxLayout.x) - 0.5;
}

// The closed-form integral over a sub-step at the fixed coordinate p (cells, curtainFixedCell): across
// (along = false) from u0 = q0 to u0 + dq, or along (along = true) from s0 = q0 to s0 + dq (km, dq either
// sign); see above. Both read the texture through the same two fetches (a third where a step along leaves
// the strip's period).
vec3 curtainIntegralAt(int c, bool along, real p, real q0, real dq)
{
    vec4 detail = uCurtainDetail[c];
    FluxTable t = fluxTable(along);
    real frameY = fluxFrameY(c);
    real halfWidth = 0.5 * uFluxStrip.y;
    real stripKm = uFluxStrip.x;
    // The ends of q: along, from s0 reduced into the strip (periodic); across, in simulation km.
    real qa = along ? mod(q0 + detail.x, stripKm) : q0 * detail.z;
    real qb = along ? qa + dq : (q0 + dq) * detail.z;
    // Along, the end may lie in the next or previous period, where the integrals continue by the
    // period's: x = kL + y gives A = A(y) + k A(L), B = B(y) + k B(L) + L (k(k − 1)/2 A(L) + k A(y)).
    real k = along ? floor(qb / stripKm) : 0.0;
    real qaRead = along ? qa : clamp(qa, -halfWidth, halfWidth);
    real qbRead = along ? qb - k * stripKm : clamp(qb, -halfWidth, halfWidth);
    vec3 lo = fluxTableAt(t, p, frameY, qaRead);
    vec3 hi = fluxTableAt(t, p, frameY, qbRead);
    if (k != 0.0) {
        vec3 period = fluxTableAt(t, p, frameY, stripKm);
        hi.y += k * period.y + stripKm * (0.5 * k * (k - 1.0) * period.x + k * hi.x);
        hi.x += k * period.x;
    }
    // Along, beyond the strip across (simulation km from its middle) there is no flux.
    if (along && abs((p + 0.5) * (uFluxStrip.y / uFluxLayout.y) - halfWidth) >= halfWidth)
        return vec3(0.0);
    if (!along) {
        lo.z = abs(qa) < halfWidth ? lo.z : 0.0;
        hi.z = abs(qb) < halfWidth ? hi.z : 0.0;
    }
    real scale = along ? 1.0 : detail.z; // simulation km per curtain km along q
    real mass = (hi.x - lo.x) / scale;
    real start = along ? qa : q0;        // q's start in the units of the moment: strip km, or curtain km
    return uFluxStrip.w * vec3(mass, (hi.y - lo.y) / (scale * scale) - start * mass, 0.5 * (lo.z + hi.z));
}

// The same at fixedKm: a sub-step that reads the flux at the middle of the coordinate it does not integrate over.
vec3 curtainIntegral(int c, bool along, real fixedKm, real q0, real dq)
{
    return curtainIntegralAt(c, along, curtainFixedCell(c, along, fixedKm), q0, dq);
}

// The width across curtain c (km) over which its flux is resolved: the frames' cell across, scaled to it.
real fluxCellAcrossKm(int c)
{
    return uFluxStrip.y / uFluxLayout.y / uCurtainDetail[c].z;
}

// The length along the curtain over which its flux is resolved (km): the frames' cell along (the
// texture interpolates linearly between cells).
real fluxCellAlongKm()
{
    return uFluxStrip.x / uFluxLayout.x;
}

// What fluxColumnPoint reads of curtain c's detail, fixed over a step: the table along q (along: the rows,
// else the columns), the frames' blend, and the simulation km per curtain km along q. Built once, outside
// the loop over pieces (llvmpipe's compiler does not hoist what does not change in a loop).
struct FluxColumns {
    FluxTable table;
    real frameY;
    real scale;
    real halfWidth; // the strip's half width across, simulation km
    bool along;
};

FluxColumns fluxColumns(int c, bool along)
{
    FluxColumns f;
    f.table = fluxTable(along);
    f.frameY = fluxFrameY(c);
    f.scale = along ? 1.0 : uCurtainDetail[c].z;
    f.halfWidth = 0.5 * uFluxStrip.y;
    f.along = along;
    return f;
}

// The running integrals and the flux (A, B, F) of the detail's column `cell` (an integer, counted
// periodically as the frames are) at q (curtain km: along, s reduced into the strip's period; across, u),
// in curtainIntegralAt's units times its peak scale: across, outside the strip, the integrals at its edge
// and no flux. One fetch.
vec3 fluxColumnPoint(FluxColumns f, real cell, real q)
{
    real qSim = q * f.scale;
    vec3 v = fluxTableAt(f.table, mod(cell, f.table.cells), f.frameY,
                         f.along ? qSim : clamp(qSim, -f.halfWidth, f.halfWidth));
    v.z = f.along || abs(qSim) < f.halfWidth ? v.z : 0.0;
    return uFluxStrip.w * vec3(v.x / f.scale, v.y / (f.scale * f.scale), v.z);
}

// A piece of a step's path between the centres of two neighbouring columns i and j = i + 1, over which q runs
// from q0 to q0 + dq and the share λ of column j runs linearly from la to lb, integrated exactly for the
// flux as the texture gives it, F = (1 − λ) F_i + λ F_j (linear between the centres in both coordinates):
// with each column's (A, B) over the piece (fluxColumnPoint at its two ends, `lo` and `hi`),
//   ∫ F dq = A_i + la (A_j − A_i) + (lb − la) (B_j − B_i) / dq,   B the moment about q0.
// (∫ F dq, ∫ (q − q0) F dq, the mean F at the ends) as curtainIntegralAt; the moment takes λ at the middle.
// The moments are differences of running integrals as large as the table's largest |q| (Q) times the
// column's whole integral, so in float their difference over (λ_b − λ_a)/dq costs up to 8 u Q/qCellKm of
// that integral where λ changes by at most one cell of q's (qCellKm) over dq, as where the path crosses
// more cells of q than of the fixed coordinate; elsewhere (beyond a curtain's end, where the pieces run
// across while s changes faster) the mass takes λ at the middle, off by at most (λ_b − λ_a) dq² |F_j' − F_i'| / 12.
vec3 bilinearPiece(vec3 loI, vec3 loJ, vec3 hiI, vec3 hiJ, real q0, real dq, real la, real lb, real qCellKm)
{
    real massI = hiI.x - loI.x;
    real massJ = hiJ.x - loJ.x;
    real momentI = hiI.y - loI.y - q0 * massI;
    real momentJ = hiJ.y - loJ.y - q0 * massJ;
    real lm = 0.5 * (la + lb);
    real mass = abs(lb - la) * qCellKm < abs(dq) ? massI + la * (massJ - massI) + (lb - la) / dq * (momentJ - momentI)
                                                 : mix(massI, massJ, lm);
    return vec3(mass, mix(momentI, momentJ, lm), 0.5 * (mix(loI.z, loJ.z, la) + mix(hiI.z, hiJ.z, lb)));
}
#else
// The smooth Gaussian does not change along a curtain: the column across is exact for any sub-step.
const bool kProfileVariesAlong = false;

// Across only (a profile constant along needs no other): the Gaussian exp(−a²/2), a = u / σ, in closed form.
vec3 curtainIntegral(int c, bool along, real fixedKm, real q0, real dq)
{
    real scale = uCurtainDetail[c].z;
    real a0 = q0 * scale;
    real a1 = (q0 + dq) * scale;
    real mass = gaussianMass(a0, a1) / scale;
    return vec3(mass, gaussianMoment(a0, a1) / (scale * scale) - q0 * mass,
                0.5 * (exp(-0.5 * a0 * a0) + exp(-0.5 * a1 * a1)));
}

real fluxCellAcrossKm(int c)
{
    return 1.0e30;
}

// Unbounded: the smooth Gaussian does not change along the curtain.
real fluxCellAlongKm()
{
    return 1.0e30;
}
#endif
