// Aurora curtains (Lawlor & Genetti 2011, sections 2-3): an emissive shell between
// uAuroraBottomKm and uAuroraTopKm. Each curtain's footprint is a spline on the sphere, sampled on
// the CPU into a dense polyline (a row of uCurtainPolylines: unit vector, arclength km). The
// footprint map (a jump-flooded nearest-point map, shaders/components/aurora/footprint_map.glsl) gives, for
// any point, the nearest curtain point and a conservative distance to it; the shader refines on
// the segments around that point to exact curtain coordinates (s along, u across), so detail is
// not limited by the map's texels. Emission = peak energy flux x profile(s, u) x the tabulated
// line emission of the curtain's electrons at this altitude (aurora/curtain_emission.glsl).
uniform real uAuroraBottomKm;
uniform real uAuroraTopKm;
uniform real uAuroraStepKm;
uniform real uAuroraResolveKm;       // sub-steps (at most 64 a step): altitude and position along a curtain change by at most this
uniform real uAuroraResolveCells;    // and the coordinate not integrated over by at most this many of the detail's cells
// True with sub_step_flux = "exact" (AURORA_EXACT_SUB_STEPS, src/components/aurora/aurora.cpp): with curtain
// detail, each curtain's part of a step integrated exactly in the detail's bilinear flux (curtainEnergyExact). A
// constant on the GPU, so that the march without it does not carry its code (llvmpipe runs both sides of a
// branch on a uniform: 1.7x the time); the CPU's march in double sets it per scene.
#ifndef EXACT_SUB_STEPS
#ifdef AURORA_EXACT_SUB_STEPS
#define EXACT_SUB_STEPS true
#else
#define EXACT_SUB_STEPS false
#endif
#endif
uniform int uSkipEmptySpace;         // 0: the naive fine march everywhere (the reference)
uniform int uCurtainCount;
uniform sampler2D uCurtainPolylines; // RGBA32F, row c: xyz unit vector, w arclength km
uniform vec4 uCurtainState[MAX_CURTAINS];  // peak energy flux erg cm^-2 s^-1, energy keV (the emission rows' key), point count,
                                           // reach km: beyond it from its centre line and its ends the curtain does not emit
uniform real uCurtainLengthKm[MAX_CURTAINS];     // the polyline's arclength, its last point's (a uniform: no fetch)
uniform real uCurtainCornerSlope[MAX_CURTAINS];  // tan(θ/2) of its polyline's largest turn θ between segments, with
                                                 // room for the float segment normals' tilt (CurtainField)
uniform real uCurtainReachKm;        // the largest reach of the curtains that emit (flux > 0) this frame: beyond it
                                     // from every centre line nothing emits

uniform sampler2D uFootprintMap;     // RGBA32F, nearest: curtain id, point index, distance km, other curtain
uniform vec3 uFootprintCentre;
uniform vec3 uFootprintEast;
uniform real uFootprintAngularRadius;
uniform real uFootprintSize;
uniform real uFootprintMarginKm;

// Point j of curtain c's polyline: unit vector, arclength km.
vec4 polylinePoint(int c, int j)
{
    COUNT_WORK(w, 1);
    return texelFetch(uCurtainPolylines, ivec2(j, c), 0);
}

// Curtain coordinates of direction n relative to curtain c, starting from polyline point i (the
// footprint map's nearest point, which can be a few texels of arclength away from the true
// nearest one): jump along the polyline by the projected along-track offset until n projects
// inside the segment or the jumps turn back (n lies off a corner's outer side, between two
// segments' ends), then take the closest of that segment and its neighbours. Each point is read once.
struct CurtainCoordinates {
    real s;         // km along the curtain (beyond its ends: negative, or more than its length)
    real u;         // km across it (signed)
    real distance;  // km from its polyline
    vec3 normal;    // unit normal of the closest segment's great circle: u grows along it
    real curvature; // 1/km, positive where the curtain bends towards +u
    real segmentKm; // length of the segment whose end gives the curvature
};

CurtainCoordinates curtainCoordinates(int c, int i, vec3 n)
{
    COUNT_WORK(y, 1);
    int last = int(uCurtainState[c].z) - 2; // index of the last segment
    int j = clamp(i, 0, last);
    vec4 a = polylinePoint(c, j);
    vec4 b = polylinePoint(c, j + 1);
    vec3 normal = segmentNormal(vec3(a), vec3(b));
    vec4 p = projectOnSegmentWithNormal(vec3(a), normal, b.w - a.w, n, uPlanetRadiusKm);
    // At most 6 jumps. The test ends the loop's body: a SIMD group runs a body as long as any lane does, and
    // llvmpipe runs it once more where the test opens it.
    int direction = 0;
    int step = int(floor(p.x / max(p.y, 1e-6)));
    int next = clamp(j + step, 0, last);
    bool jumping = next != j;
    int jump = 0;
    do {
        if (jumping) {
            direction = step;
            // A jump to the next or previous segment keeps the point it shares with this one.
            vec4 start = next == j + 1 ? b : polylinePoint(c, next);
            b = next == j - 1 ? a : polylinePoint(c, next + 1);
            a = start;
            j = next;
            normal = segmentNormal(vec3(a), vec3(b));
            p = projectOnSegmentWithNormal(vec3(a), normal, b.w - a.w, n, uPlanetRadiusKm);
            step = int(floor(p.x / max(p.y, 1e-6)));
            next = clamp(j + step, 0, last);
            jumping = ++jump < 6 && next != j && step * direction >= 0;
        }
    } while (jumping);
    CurtainCoordinates best;
    // The curtain's curvature at the segment's nearer end, from the point beyond it (polylineCurvature, the
    // turn held to the polyline's largest, θ = 2 atan(uCurtainCornerSlope)): one fetch; 0 where the polyline
    // is one segment.
    bool atStart = (p.x < 0.5 * p.y && j > 0) || j == last;
    vec4 beyond = polylinePoint(c, clamp(atStart ? j - 1 : j + 2, 0, last + 1));
    vec4 corner = atStart ? a : b;
    best.curvature = last > 0 ? polylineCurvature(vec3(corner), vec3(beyond), normal, p.y, abs(beyond.w - corner.w),
                                                  uPlanetRadiusKm, 2.0 * atan(uCurtainCornerSlope[c]))
                              : 0.0;
    best.segmentKm = p.y;
    best.distance = length(vec2(p.z, p.w));
    best.u = p.z;
    best.s = a.w + p.x;
    best.normal = normal;
    // The segments before (point j − 1 to a) and after (b to point j + 2), where they exist. A neighbour
    // turning by θ at the shared end can be nearer only where n projects within |u| tan(θ/2) of that end (on
    // the corner's inner side; on its outer side the shared end is the neighbour's nearest point, no nearer
    // than |u|), so it is read only there; 50 m more covers the float distances' ties.
    real endZoneKm = abs(p.z) * uCurtainCornerSlope[c] + 0.05;
    // The sides to read, the one before first; as for the jumps, the test ends the loop's body.
    bool before = !(j == 0 || p.x > endZoneKm);
    bool after = !(j == last || p.x < p.y - endZoneKm);
    int sides = (before ? 1 : 0) + (after ? 1 : 0);
    int side = before ? 0 : 1;
    int read = 0;
    do {
        if (sides > 0) {
            vec4 other = polylinePoint(c, side == 0 ? j - 1 : j + 2);
            vec4 start = side == 0 ? other : b;
            vec4 end = side == 0 ? a : other;
            vec3 sideNormal = segmentNormal(vec3(start), vec3(end));
            vec4 q = projectOnSegmentWithNormal(vec3(start), sideNormal, end.w - start.w, n, uPlanetRadiusKm);
            real distance = length(vec2(q.z, q.w));
            if (distance < best.distance) {
                best.s = start.w + q.x;
                best.u = q.z;
                best.distance = distance;
                best.normal = sideNormal;
            }
        }
        side = 1;
    } while (++read < sides);
    return best;
}

// Linear sRGB emitted per km of path per unit of curtain c's flux profile at the point o + t d.
vec3 curtainEmissionAt(vec3 o, vec3 d, real t, int c)
{
    COUNT_WORK(w, 1);
    return curtainEmissionRgbPerKm(length(o + t * d) - uPlanetRadiusKm, c);
}

// The part of the interval [range.x, range.y] of t where x(t) = x_m + rate (t − t_m) lies within
// [lo, hi] (empty: x ≥ y).
vec2 intersectLinearBand(vec2 range, real xm, real rate, real tm, real lo, real hi)
{
    if (abs(rate) < 1e-9)
        return xm >= lo && xm <= hi ? range : vec2(range.y, range.y);
    real ta = tm + (lo - xm) / rate;
    real tb = tm + (hi - xm) / rate;
    return vec2(max(range.x, min(ta, tb)), min(range.y, max(ta, tb)));
}

// The fastest the footprint of the ray o + t d (km) can move, in km on the ground per km of ray, from the
// point p onward within the aurora shell: the footprint n = x/|x| moves at |dn/dt| = sin ζ / r = b / r², b
// = |x × d| the ray's (constant) distance of closest approach to the planet's centre, so R b / r² on the
// ground. r only grows ahead of a rising ray (p·d ≥ 0); a falling one gets no lower than b or the shell's
// bottom (1 km below it covers the float segment ends). At most 1 above the ground.
real footprintSpeedBound(vec3 p, vec3 d)
{
    real r = length(p);
    real b = length(cross(p, d));
    real lowest = dot(p, d) >= 0.0 ? r : max(b, uPlanetRadiusKm + uAuroraBottomKm - 1.0);
    return clamp(uPlanetRadiusKm * b / (lowest * lowest) * 1.0001, 1e-3, 1.0);
}

// What the footprint map says of the step [t0, t1] of the ray o + t d (km): skipKm, how much farther along
// the ray the following steps' midpoints must lie before a curtain can reach them (the map's lower bound
// from this midpoint less the largest reach and half a step, over the footprint's largest speed,
// footprintSpeedBound), and the curtains that can reach the step: (curtain, polyline point) of the nearest curtain and, where
// curtains overlap, of the nearest point of another (the map's fourth channel,
// src/components/aurora/physics/footprint_map.h); curtain −1 where there is none, or where that curtain
// has no flux or lies farther than its reach + step/2 from the midpoint.
struct StepCandidates {
    real skipKm;
    vec4 candidates;
};

bool canReachStep(int c, real lowerKm, real len)
{
    return uCurtainState[c].x > 0.0 && lowerKm - 0.5 * len <= uCurtainState[c].w;
}

StepCandidates stepCandidates(vec3 o, vec3 d, real t0, real t1)
{
    StepCandidates step;
    step.candidates = vec4(-1.0);
    real len = t1 - t0;
    vec3 p = o + 0.5 * (t0 + t1) * d;
    vec3 n = normalize(p);
    real speed = footprintSpeedBound(p, d);
    real outsideKm = footprintMapOutsideKm(n, uFootprintCentre, uFootprintAngularRadius, uPlanetRadiusKm);
    if (outsideKm > 0.0) {
        // The map's cap holds every curtain with its reach (CPU side), so nothing emits out here.
        step.skipKm = outsideKm / speed;
        return step;
    }
    vec2 texel = footprintMapTexel(footprintMapCoord(n, uFootprintCentre, uFootprintEast, uFootprintAngularRadius),
                                   uFootprintSize);
    vec4 nearest = texelFetch(uFootprintMap, ivec2(texel), 0);
    COUNT_WORK(w, 1);
    real lowerKm = footprintConservativeKm(nearest.z, uFootprintMarginKm);
    // A step whose midpoint lies farther than the largest reach + step/2 from every curtain emits nothing.
    step.skipKm = (lowerKm - uCurtainReachKm - 0.5 * uAuroraStepKm) / speed;
    if (step.skipKm > 0.0)
        return step;
    // lowerKm bounds the distance to every curtain from below, so it tests each candidate's own reach.
    if (nearest.x >= 0.0 && canReachStep(int(nearest.x), lowerKm, len)) {
        step.candidates.x = nearest.x;
        step.candidates.y = nearest.y;
    }
    if (nearest.w >= 0.0) {
        real second = floor(nearest.w / 65536.0); // the map packs curtain · 65536 + point
        if (canReachStep(int(second), lowerKm, len)) {
            step.candidates.z = second;
            step.candidates.w = nearest.w - 65536.0 * second;
        }
    }
    return step;
}

// Whether a curtain of length lengthKm emits at its coordinates (s, u) (km): beyond its reach, across or
// around its ends, it does not.
bool withinReach(real s, real u, real lengthKm, real reach)
{
    real beyondEnds = max(max(-s, s - lengthKm), 0.0);
    return length(vec2(u, beyondEnds)) <= reach;
}

// Where the ray, u(t) = u_m + u' (t − t_m) and s(t) = s_m + s' (t − t_m), meets the circles of radius
// `reach` around the curtain's ends s = 0 and s = lengthKm: the roots t of u² + (s − end)² = reach², by
// the stable quadratic formula (1e30 where there is none).
vec4 endReachCuts(CurtainCoordinates cc, real tm, real uRate, real sRate, real reach, real lengthKm)
{
    vec4 cuts = vec4(1.0e30);
    real a = uRate * uRate + sRate * sRate;
    for (int e = 0; e < 2; ++e) {
        real offset = cc.s - (e == 0 ? 0.0 : lengthKm);
        real halfB = cc.u * uRate + offset * sRate;
        real c = cc.u * cc.u + offset * offset - reach * reach;
        real discriminant = halfB * halfB - a * c;
        if (a > 0.0 && discriminant > 0.0) {
            real q = -(halfB + (halfB >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
            cuts[2 * e] = tm + q / a;
            cuts[2 * e + 1] = q != 0.0 ? tm + c / q : cuts[2 * e];
        }
    }
    return cuts;
}

// The part of `range` (t, km) within curtain c's reach, the stadium |u| <= reach over 0 <= s <= lengthKm
// with a disc of radius reach around either end (u and s linear in t as in endReachCuts): a convex
// region, so a single interval, from the first entry to the last exit of its three parts.
vec2 withinStadium(vec2 range, CurtainCoordinates cc, real tm, real uRate, real sRate, real reach, real lengthKm)
{
    if (abs(uRate) < 1e-9 && abs(sRate) < 1e-9) // a footprint that stays put (as intersectLinearBand)
        return withinReach(cc.s, cc.u, lengthKm, reach) ? range : vec2(range.y, range.y);
    vec2 band = intersectLinearBand(range, cc.u, uRate, tm, -reach, reach);
    vec2 body = intersectLinearBand(band, cc.s, sRate, tm, 0.0, lengthKm);
    vec2 hull = body.x < body.y ? body : vec2(1.0e30, -1.0e30);
    vec4 cuts = endReachCuts(cc, tm, uRate, sRate, reach, lengthKm);
    for (int e = 0; e < 2; ++e) {
        vec2 disc = vec2(max(min(cuts[2 * e], cuts[2 * e + 1]), band.x), min(max(cuts[2 * e], cuts[2 * e + 1]), band.y));
        if (cuts[2 * e] < 1.0e30 && disc.x < disc.y)
            hull = vec2(min(hull.x, disc.x), max(hull.y, disc.y));
    }
    return hull.x < hull.y ? hull : vec2(range.y, range.y);
}

// What a sub-step or piece [ta, ta + len] of the ray (km) adds to its run, from its closed-form column
// (∫ profile dq, ∫ (q − q0) profile dq, mean profile at its ends: curtainIntegral, bilinearPiece) over
// the change dq = rate · len of the integrated coordinate: (∫ profile dt in km, ∫ t profile dt in km²),
// at the flux-weighted mean position from the first moment; the midpoint rule where q changes by less
// than 1 m or where the caller finds the closed form rounder than it (`rounded`); nothing where the mass
// is not positive.
vec2 runShare(vec3 column, real dq, real rate, real ta, real len, bool rounded)
{
    bool pointLike = rounded || abs(dq) < 1e-3;
    real mass = pointLike ? column.z * len : column.x / rate;
    if (mass <= 0.0)
        return vec2(0.0);
    real tMean = pointLike ? ta + 0.5 * len : clamp(ta + column.y / column.x / rate, ta, ta + len);
    return vec2(mass, mass * tMean);
}

// The emission of a run of sub-steps or pieces that share one: its summed runShare (∫ profile dt in km,
// ∫ t profile dt in km²) times curtain c's emission at the run's flux-weighted mean position t̄, faded
// there by its distance beyond the curtain's ends (curtainEndFade; s = s_m + s' (t̄ − t_m), as in
// integrateCurtains).
vec3 runEnergy(vec3 o, vec3 d, vec2 sums, int c, real sm, real sRate, real tm)
{
    if (sums.x <= 0.0)
        return vec3(0.0);
    real t = sums.y / sums.x;
    real s = sm + sRate * (t - tm);
    real beyondEnd = max(max(-s, s - uCurtainLengthKm[c]), 0.0);
    return sums.x * curtainEndFade(beyondEnd, uCurtainState[c].w) * curtainEmissionAt(o, d, t, c);
}

#ifdef HAS_CURTAIN_DETAIL
// The energy (per unit of peak flux) of curtain c over the part `span` of a step of the ray o + t d (km),
// its flux integrated exactly along the ray's slanted path through the detail's bilinear flux
// (sub_step_flux = "exact"). As in integrateCurtains, q (u across, s along: `alongMode`) and the other,
// fixed coordinate f (s across, kept within the curtain's ends; u along) run linearly from the step's
// midpoint tm; p = f / (cell km) counts the detail's cells. The path is cut into pieces where
//  - p passes a cell centre: between two centres the flux is a linear mix of the columns there, which
//    bilinearPiece integrates exactly;
//  - f meets its band's edge: across, a curtain end, beyond which p stays at the end's; along, the strip's
//    edge, beyond which there is no flux;
//  - the altitude has changed by uAuroraResolveKm since the last such cut (and, where the part reaches beyond
//    an end, !betweenEnds, s by curtainEndFadeStepKm): the pieces between two of these cuts, a run, share one emission,
//    faded beyond the ends, at their flux-weighted mean position (runEnergy);
//  - along, s leaves the strip's period;
//  - the path meets the circle of the curtain's reach around either end (endReachCuts), so that each
//    piece lies wholly within or beyond the reach there.
// A piece reads the two columns at its end (2 fetches), and the next one starts from those, reading a third
// where it has crossed into the next cell: about 3 fetches a cell crossed. Where it holds no columns at its
// start, it reads them first, as the end of a piece of no length. Where p would cross more than 64
// centres, the pieces take `stride` cells at a time, each with the two columns around its middle (λ kept
// in [0, 1]): no worse than a column at its middle.
vec3 curtainEnergyExact(vec3 o, vec3 d, int c, CurtainCoordinates cc, real tm, vec2 span, real uRate, real sRate,
                        real hRate, bool alongMode, bool betweenEnds)
{
    real reach = uCurtainState[c].w;
    real lengthKm = uCurtainLengthKm[c];
    real stripKm = uFluxStrip.x;
    real rate = alongMode ? sRate : uRate; // q's, curtain km per km of ray
    real fixedRate = alongMode ? uRate : sRate;
    real halfWidthKm = 0.5 * uFluxStrip.y / uCurtainDetail[c].z;
    vec2 band = intersectLinearBand(span, alongMode ? cc.u : cc.s, fixedRate, tm, alongMode ? -halfWidthKm : 0.0,
                                    alongMode ? halfWidthKm : lengthKm);
    real uStart = cc.u + uRate * (span.x - tm);
    real sStart = cc.s + sRate * (span.x - tm);
    real fixedStart = alongMode ? uStart : clamp(sStart, 0.0, lengthKm);
    real p = curtainFixedCell(c, alongMode, fixedStart); // not reduced again as it runs: columns are read periodically
    real pRate = fixedRate / (alongMode ? fluxCellAcrossKm(c) : fluxCellAlongKm());
    real qCellKm = alongMode ? fluxCellAlongKm() : fluxCellAcrossKm(c);
    real stride = max(1.0, ceil(abs(pRate) * (span.y - span.x) / 64.0));
    real group = pRate < 0.0 ? ceil(p / stride) - 1.0 : floor(p / stride); // p lies in [group, group + 1] strides
    real fadeRuns = betweenEnds ? 0.0 : abs(sRate) * (span.y - span.x) / curtainEndFadeStepKm(reach);
    real runs = clamp(ceil(max(abs(hRate) * (span.y - span.x) / uAuroraResolveKm, fadeRuns)), 1.0, 64.0);
    real runKm = (span.y - span.x) / runs;
    real run = 0.0;
    real q = alongMode ? mod(sStart + uCurtainDetail[c].x, stripKm) : uStart;
    vec4 endCuts = endReachCuts(cc, tm, uRate, sRate, reach, lengthKm);
    FluxColumns columns = fluxColumns(c, alongMode);
    // The two columns' values at the piece's start, of the pair from column `held` (none: −1e30).
    real held = -1.0e30;
    vec3 lo = vec3(0.0);
    vec3 loNext = vec3(0.0);
    vec3 energy = vec3(0.0);
    vec2 runSums = vec2(0.0); // the run's summed runShare
    real ta = span.x;
    // The pieces of one run, then its emission: evaluated once a run, not in every piece's branch. Both loops
    // test at the end of their bodies (span is not empty). At most 64 runs, 65 strides, 2 band edges, 4 reach
    // circles, the strip's periods and a first read after each of these but the runs and strides: the bound
    // of 256 pieces never binds.
    int piece = 0;
    do {
        do {
            bool inBand = ta >= band.x && ta < band.y;
            real pRateNow = inBand ? pRate : 0.0;
            real tCentre = pRateNow > 0.0 ? ta + ((group + 1.0) * stride - p) / pRateNow
                         : pRateNow < 0.0 ? ta + (group * stride - p) / pRateNow : 1.0e30;
            real tBand = ta < band.x ? band.x : ta < band.y ? band.y : 1.0e30;
            real tRun = run + 1.0 >= runs ? span.y : span.x + (run + 1.0) * runKm;
            real tWrap = !alongMode || sRate == 0.0 ? 1.0e30 : ta + ((sRate > 0.0 ? stripKm : 0.0) - q) / sRate;
            real tEnd = 1.0e30;
            for (int k = 0; k < 4; ++k)
                tEnd = endCuts[k] > ta ? min(tEnd, endCuts[k]) : tEnd;
            real tb = max(min(min(min(tCentre, tBand), min(tRun, tWrap)), min(tEnd, span.y)), ta);
            real len = tb - ta;
            bool centre = tCentre <= tb;
            bool wrap = tWrap <= tb;
            real pb = centre ? (pRateNow > 0.0 ? group + 1.0 : group) * stride : p + pRateNow * len;
            real qb = wrap ? (sRate > 0.0 ? stripKm : 0.0) : q + rate * len;
            real tMid = ta + 0.5 * len;
            real u = cc.u + uRate * (tMid - tm);
            real s = cc.s + sRate * (tMid - tm);
            // Along, nor beyond the strip.
            bool emits = withinReach(s, u, lengthKm, reach) && (inBand || !alongMode);
            real cell = clamp(floor(0.5 * (p + pb)), group * stride, (group + 1.0) * stride - 1.0);
            // Where the columns at its start are not held (the first piece, or the first that emits after one
            // that did not or after a wrap), the piece first reads them as the end of a piece of no length, and
            // then runs again: every piece then reads its two columns at its end and, where it has crossed into
            // the next cell, one at its start. (A SIMD group pays for a branch's fetch whenever any lane takes
            // it, llvmpipe even when none does; this way a piece has one such fetch, not two.)
            bool prime = emits && len > 0.0 && abs(held - cell) > 1.0;
            if (!emits) {
                held = -1.0e30;
            } else if (len > 0.0) {
                if (held != cell && !prime) {
                    // Into the next cell up or down: one of the held columns is the new pair's.
                    bool down = held == cell + 1.0;
                    vec3 read = fluxColumnPoint(columns, down ? cell : cell + 1.0, q);
                    vec3 kept = down ? lo : loNext;
                    lo = down ? read : kept;
                    loNext = down ? kept : read;
                }
                real qEnd = prime ? q : qb;
                vec3 hi = fluxColumnPoint(columns, cell, qEnd);
                vec3 hiNext = fluxColumnPoint(columns, cell + 1.0, qEnd);
                if (!prime) {
                    COUNT_WORK(z, 1);
                    real dq = qb - q;
                    real la = clamp(p - cell, 0.0, 1.0);
                    real lb = clamp(pb - cell, 0.0, 1.0);
                    vec3 column = bilinearPiece(lo, loNext, hi, hiNext, q, dq, la, lb, qCellKm);
                    // The closed form is a difference of running integrals held in float texels: its mass errs by
                    // about 2u of their sizes (u = 2^-24), and where λ changes along the piece by 2u of the
                    // moments' over dq too (bilinearPiece). The end-point rule (the ends' mean profile times dq)
                    // errs by about half the profile's change over the piece times dq, where the profile runs
                    // smoothly between the ends. A ray that barely moves across the detail (looking along a
                    // curtain, straight up inside it) takes the rule where that is below the mass's rounding and
                    // the closed form agrees with the rule within its whole rounding: a piece can run through
                    // whole cells of q, and the rule does not see a sheet between two ends where the flux is nil.
                    real sizes = abs(lo.x) + abs(loNext.x) + abs(hi.x) + abs(hiNext.x);
                    real momentSizes = abs(lo.y) + abs(loNext.y) + abs(hi.y) + abs(hiNext.y) + abs(q) * sizes;
                    real slope = abs(lb - la) * qCellKm < abs(dq) ? abs(lb - la) / abs(dq) : 0.0;
                    real rounding = 1.2e-7 * sizes;
                    real endPoint = 0.5 * abs(dq) * abs(mix(hi.z, hiNext.z, lb) - mix(lo.z, loNext.z, la));
                    bool rounded = endPoint < rounding &&
                                   abs(column.x - column.z * dq) <= 2.0 * (rounding + 1.2e-7 * slope * momentSizes);
                    runSums += runShare(column, dq, rate, ta, len, rounded);
                }
                lo = hi;
                loNext = hiNext;
                held = cell;
            }
            if (prime)
                continue;
            if (wrap) {
                q = sRate > 0.0 ? 0.0 : stripKm; // the same point of the periodic strip, its integrals from 0 again
                held = -1.0e30;
            } else {
                q = qb;
            }
            if (centre)
                group += pRateNow > 0.0 ? 1.0 : -1.0;
            p = pb;
            ta = tb;
            if (tRun <= tb) {
                run += 1.0;
                ++piece;
                break;
            }
        } while (++piece < 256 && ta < span.y);
        energy += runEnergy(o, d, runSums, c, cc.s, sRate, tm);
        runSums = vec2(0.0);
    } while (piece < 256 && ta < span.y);
    return energy;
}
#endif

// Curtain c's emission (per unit of its peak flux) over the part `chord` [ta, tb] of a step of the ray
// o + t d (km), with its coordinates linear about the chord's midpoint tm: u(t) = u_m + u' (t − t_m),
// s(t) = s_m + s' (t − t_m) (cc.u, cc.s, uRate, sRate). Only the part of the chord within the curtain's
// reach (of its centre line, and of its ends) can emit. That part is cut into sub-steps over which
// the altitude changes by at most uAuroraResolveKm; on each the emission is integrated in closed form
// over the coordinate that changes through more of the detail's cells, across the curtain,
//   ∫ flux(s, u(t)) E(h(t)) dt ≈ E(h(t̄)) · (1/u') ∫_{u(ta)}^{u(tb)} flux(s_mid, u) du,
// or along it (s and u exchanged), and the other coordinate changes by at most uAuroraResolveCells of
// the detail's cells (along, also by at most uAuroraResolveKm, alongResolveKm); with EXACT_SUB_STEPS the
// flux is integrated exactly along the slanted path instead, in pieces cut at the detail's cell centres
// (curtainEnergyExact). t̄ is the flux-weighted mean position of the sub-step, from the first moment
// (curtain_profile.glsl, curtainIntegral). A sub-step that changes the integrated coordinate by less than
// 1 m takes the midpoint rule.
vec3 curtainChordEnergy(vec3 o, vec3 d, int c, CurtainCoordinates cc, vec2 chord, real uRate, real sRate, real hRate,
                        real alongResolveKm)
{
    real tm = 0.5 * (chord.x + chord.y);
    real reach = uCurtainState[c].w;
    real lengthKm = uCurtainLengthKm[c];
    // The sub-steps cover the part within reach alone, so that none straddles the reach's edge around an end.
    vec2 within = withinStadium(chord, cc, tm, uRate, sRate, reach, lengthKm);
    if (within.x >= within.y)
        return vec3(0.0);
    real start = within.x;
    real span = within.y - within.x;
    real sStart = cc.s + sRate * (within.x - tm);
    real sEnd = cc.s + sRate * (within.y - tm);
    bool betweenEnds = min(sStart, sEnd) >= 0.0 && max(sStart, sEnd) <= lengthKm;
#ifdef HAS_CURTAIN_DETAIL
    if (EXACT_SUB_STEPS) {
        // Exact along the slanted path, integrated in closed form over the coordinate whose cells it
        // crosses more of, cut at the other's cell centres.
        bool moreAlong = abs(uRate) / fluxCellAcrossKm(c) < abs(sRate) / fluxCellAlongKm();
        return curtainEnergyExact(o, d, c, cc, tm, within, uRate, sRate, hRate, moreAlong && betweenEnds, betweenEnds);
    }
#endif
    // A step that moves through more of the detail's cells along than across (and stays between the
    // curtain's ends) is integrated along in closed form, with sub-steps that bound the change across;
    // any other, across, with sub-steps that bound the change along.
    real alongParts = abs(sRate) / alongResolveKm;
    real acrossParts = abs(uRate) / (uAuroraResolveCells * fluxCellAcrossKm(c));
    bool alongMode = kProfileVariesAlong && acrossParts < alongParts && betweenEnds;
    real resolveParts = alongMode ? acrossParts : alongParts;
    // Beyond an end, the sub-steps also move s by at most curtainEndFadeStepKm.
    real fadeKm = curtainEndFadeStepKm(reach);
    real fadeParts = betweenEnds ? 0.0 : abs(sRate) / fadeKm;
    int parts = int(clamp(ceil(max(max(abs(hRate) / uAuroraResolveKm, resolveParts), fadeParts) * span), 1.0, 64.0));
    real part = span / real(parts);
    COUNT_WORK(z, parts);
    // Runs of sub-steps over which the altitude changes by at most uAuroraResolveKm (and, beyond an end, s
    // by at most fadeKm) share one emission, at their flux-weighted mean position (where it changes less
    // than that over the whole chord, all the chord's sub-steps do).
    real runParts = min(floor(uAuroraResolveKm / max(abs(hRate) * part, 1e-6)),
                        betweenEnds ? 64.0 : floor(fadeKm / max(abs(sRate) * part, 1e-6)));
    int run = int(clamp(runParts, 1.0, 64.0));
    // The sub-step's change in the coordinate integrated in closed form, and its rate per km of ray.
    real rate = alongMode ? sRate : uRate;
    real change = rate * part;
    vec3 energy = vec3(0.0);
    vec2 runSums = vec2(0.0); // the run's summed runShare
    for (int i = 0; i < parts; ++i) {
        real ta = start + real(i) * part;
        real tMid = ta + 0.5 * part;
        real u = cc.u + uRate * (tMid - tm);
        real s = cc.s + sRate * (tMid - tm);
        if (withinReach(s, u, lengthKm, reach)) {
            // (∫ profile, ∫ offset from the sub-step's start × profile, mean profile at its ends) over
            // the integrated coordinate.
            real q0 = (alongMode ? s : u) - 0.5 * change;
            vec3 column = curtainIntegral(c, alongMode, alongMode ? u : clamp(s, 0.0, lengthKm), q0, change);
            runSums += runShare(column, change, rate, ta, part, false);
        }
        if ((i + 1) % run == 0 || i == parts - 1) {
            energy += runEnergy(o, d, runSums, c, cc.s, sRate, tm);
            runSums = vec2(0.0);
        }
    }
    return energy;
}

// The emission of the ray o + t d over the step [t0, t1] (km) of the curtains that can reach it
// (stepCandidates), as linear sRGB radiance. The curtain coordinates are found once, at the step's
// midpoint t_m (which decides which curtains are near, as a point sample did), and carried over the step
// to second order in t − t_m. A curtain that bends (curvature κ, towards +u where positive) carries a
// point u from its centre line as a curve does its Frenet frame: the nearest point runs at
// s' = v_T / (1 − κu), v_T the footprint's speed along the segment, faster on the inner side, and
// u'' = −κ (1 − κu) s'², s'' = 2κ u' s' / (1 − κu). The step is cut into chords short enough that these
// move neither coordinate by more than kChordCells of the detail's cells off its tangent line at the
// chord's midpoint (ℓ² |x''| / 8 over a chord of ℓ km; at most 8 chords), and each chord is integrated
// with those tangent lines (curtainChordEnergy): the lines of two neighbouring chords meet at their shared
// end. (The smooth profile, with no cells, takes one chord.)
const real kChordCells = 0.05;

vec3 integrateCurtains(vec3 o, vec3 d, real t0, real t1, vec4 candidates)
{
    vec3 radiance = vec3(0.0);
    real tm = 0.5 * (t0 + t1);
    real len = t1 - t0;
    vec3 p = o + tm * d;
    real r = length(p);
    vec3 n = p / r;
    // How fast the footprint moves per km of ray, dn/dt = (d − n (n·d)) / r, and the altitude, dh/dt = n·d.
    vec3 footprintRate = (d - n * dot(n, d)) / r;
    real hRate = dot(n, d);
    // Integrated across, a sub-step reads the flux at one position along: the sub-steps resolve it to
    // uAuroraResolveKm or, finer, to uAuroraResolveCells of the detail's cells along. The fluxes of
    // overlapping curtains add.
    real alongResolveKm = min(uAuroraResolveKm, uAuroraResolveCells * fluxCellAlongKm());
    // The candidates that can reach the step (one or two), the first first. The loop's test ends its body: a
    // SIMD group then evaluates a second curtain only where one of its lanes has one (llvmpipe runs a loop's
    // body once more where the test opens it).
    vec4 pair = candidates.x >= 0.0 ? candidates : vec4(candidates.z, candidates.w, candidates.x, candidates.y);
    int count = (candidates.x >= 0.0 ? 1 : 0) + (candidates.z >= 0.0 ? 1 : 0);
    int k = 0;
    do {
        vec2 candidate = k == 0 ? vec2(pair.x, pair.y) : vec2(pair.z, pair.w);
        if (candidate.x < 0.0)
            continue;
        int c = int(candidate.x);
        CurtainCoordinates cc = curtainCoordinates(c, int(candidate.y), n);
        if (cc.distance - 0.5 * len > uCurtainState[c].w)
            continue;
        // u = R asin(n·normal), so du/dt = R (normal·dn/dt) / √(1 − (n·normal)²); s runs along
        // cross(normal, n), the direction from the segment's start to its end.
        real across = dot(n, cc.normal);
        real scale = uPlanetRadiusKm * inversesqrt(max(1.0 - across * across, 1e-12));
        real uRate = scale * dot(cc.normal, footprintRate);
        // The polyline is straight within a segment of L km and turns at its ends: a step whose footprint
        // runs S km along turns by κ min(S, L) on average, so it takes the curvature κ min(1, S / L).
        real straightRate = scale * dot(cross(cc.normal, n), footprintRate);
        real curvature = cc.curvature * min(1.0, abs(straightRate) * len / max(cc.segmentKm, 1e-6));
        // (1 − κu) kept above 1/4: nearer the centre of curvature than that, no curtain reaches.
        real bend = max(1.0 - curvature * cc.u, 0.25);
        real sRate = straightRate / bend;
        vec2 acceleration = curvature * vec2(-bend * sRate * sRate, 2.0 * uRate * sRate / bend); // u'', s''
        real bentCells = 0.125 * len * len * max(abs(acceleration.x) / fluxCellAcrossKm(c),
                                                 abs(acceleration.y) / fluxCellAlongKm());
        int chords = int(clamp(ceil(sqrt(bentCells / kChordCells)), 1.0, 8.0));
        real chordKm = len / real(chords);
        vec3 energy = vec3(0.0);
        int h = 0;
        do {
            real tc = t0 + (real(h) + 0.5) * chordKm;
            real dt = tc - tm;
            CurtainCoordinates chord = cc;
            chord.u = cc.u + dt * (uRate + 0.5 * acceleration.x * dt);
            chord.s = cc.s + dt * (sRate + 0.5 * acceleration.y * dt);
            energy += curtainChordEnergy(o, d, c, chord, vec2(tc - 0.5 * chordKm, tc + 0.5 * chordKm),
                                         uRate + acceleration.x * dt, sRate + acceleration.y * dt, hRate, alongResolveKm);
        } while (++h < chords);
        radiance += uCurtainState[c].x * energy;
    } while (++k < count);
    return radiance;
}

// The steps of a ray through the aurora shell's two segments (km; empty where x >= y): on each segment's
// grid t_k = seg.x + k·uAuroraStepKm (its last step ends at seg.y), numbered through both, the first
// segment's steps and then the second's.
struct ShellSteps {
    vec2 first;
    vec2 second;
    int firstCount;
    int count;
};

int segmentSteps(vec2 seg)
{
    // The bound only guards against an absurd segment (4e6 steps is beyond any ray through the shell).
    return seg.x < seg.y ? int(min(ceil((seg.y - seg.x) / uAuroraStepKm), 4.0e6)) : 0;
}

// Where a march through ShellSteps stands: at step k and, where that is a step some curtain can reach, its
// ends t0, t1 (km) and candidates.
struct MarchPosition {
    int k;
    real t0;
    real t1;
    StepCandidates step;
};

// From step k on, the first step that some curtain can reach, or k = count where none is: the map read step
// by step. With skipping, long jumps where the footprint map proves no curtain is near (the footprint moves
// at most footprintSpeedBound km on the ground per km of ray) go over whole steps only, landing on the same
// grid, and at most onto the second segment's first step: the skipping march evaluates a subset of the
// naive march's steps, and every step it leaves out has its midpoint farther than the largest reach +
// step/2 from every curtain, where integrateCurtains adds nothing, so both give the same sum
// (tests/render/skipping_test.cpp).
MarchPosition nextReachableStep(vec3 o, vec3 d, ShellSteps steps, MarchPosition m)
{
    // The test ends the loop's body, which a lane that starts past the last step leaves at once.
    do {
        if (m.k >= steps.count)
            break;
        bool inFirst = m.k < steps.firstCount;
        vec2 seg = inFirst ? steps.first : steps.second;
        m.t0 = seg.x + real(inFirst ? m.k : m.k - steps.firstCount) * uAuroraStepKm;
        m.t1 = min(m.t0 + uAuroraStepKm, seg.y);
        m.step = stepCandidates(o, d, m.t0, m.t1);
        COUNT_RAY_WORK(1);
        COUNT_WORK(x, 1);
        if (m.step.candidates.x >= 0.0 || m.step.candidates.z >= 0.0)
            break;
        // A step j steps on can emit only where j·step >= skipKm: the next one to read is ceil(skipKm / step) on.
        int jump = uSkipEmptySpace != 0 ? int(clamp(ceil(m.step.skipKm / uAuroraStepKm), 1.0, 4.0e6)) : 1;
        m.k = inFirst ? min(m.k + jump, steps.firstCount) : m.k + jump;
    } while (m.k < steps.count);
    return m;
}

// The aurora shell between uAuroraBottomKm and uAuroraTopKm: a ray may cross it twice (in front of the
// planet's limb and behind it); each part is seen through the lower atmosphere if it lies behind it. Each
// step [t_k, t_k+1] of both parts (ShellSteps) that some curtain can reach is integrated across those
// curtains by integrateCurtains.
// Neighbouring pixels run in lockstep (the SIMD lanes of a CPU rasterizer, a GPU's warps): a step that
// integrates curtains costs every lane of the group its time, whatever the others do, and llvmpipe runs
// every branch's body and every loop's body at least once, whatever the lanes decide. So each ray first
// reads the map step by step until it reaches a step that some curtain can reach (nextReachableStep), and
// only then integrates that step: the lanes integrate their near steps together, while their cheap steps in
// between run in the inner loop. One loop marches both parts, and its test ends its body, which integrates
// a step and finds the next: a group passes through integrateCurtains once for each step that one of its
// lanes integrates (at least once on llvmpipe). The same steps in the same order as one loop over all of
// them, so the same image (docs/aurora-physics.md).
Ray shadeAurora(Ray ray)
{
    ShellSegments shell = rayShell(ray.origin, ray.direction, uPlanetRadiusKm + uAuroraBottomKm,
                                   ray.altitude - uAuroraBottomKm, uPlanetRadiusKm + uAuroraTopKm,
                                   ray.altitude - uAuroraTopKm, ray.end);
    ShellSteps steps;
    steps.first = shell.first;
    steps.second = shell.second;
    steps.firstCount = segmentSteps(shell.first);
    steps.count = steps.firstCount + segmentSteps(shell.second);
    MarchPosition m;
    m.k = 0;
    m.t0 = 0.0;
    m.t1 = 0.0;
    m.step.skipKm = 0.0;
    m.step.candidates = vec4(-1.0);
    m = nextReachableStep(ray.origin, ray.direction, steps, m);
    vec3 first = vec3(0.0);
    vec3 second = vec3(0.0);
    do {
        if (m.k < steps.count) {
            vec3 emission = integrateCurtains(ray.origin, ray.direction, m.t0, m.t1, m.step.candidates);
            if (m.k < steps.firstCount)
                first += emission;
            else
                second += emission;
            ++m.k;
            m = nextReachableStep(ray.origin, ray.direction, steps, m);
        }
    } while (m.k < steps.count);
    if (shell.first.x < shell.first.y)
        ray.radiance += first * transmittanceTo(ray, shell.first);
    if (shell.second.x < shell.second.y)
        ray.radiance += second * transmittanceTo(ray, shell.second);
    return ray;
}
