// Aurora curtains (Lawlor & Genetti 2011, sections 2-3): an emissive shell between
// uAuroraBottomKm and uAuroraTopKm. Each curtain's footprint is a spline on the sphere, sampled on
// the CPU into a dense polyline (a row of uCurtainPolylines: unit vector, arclength km). The
// footprint map (a jump-flooded nearest-point map, shaders/components/aurora/footprint_map.glsl) gives, for
// any point, the nearest curtain point and a conservative distance to it; the shader refines on
// the segments around that point to exact curtain coordinates (s along, u across), so detail is
// not limited by the map's texels. Emission = peak energy flux x profile(s, u) x the tabulated
// line emission of the curtain's electrons at this altitude (aurora/deposition.glsl).
uniform float uAuroraBottomKm;
uniform float uAuroraTopKm;
uniform float uAuroraStepKm;
uniform int uSkipEmptySpace;         // 0: the naive fine march everywhere (the reference)
uniform int uCurtainCount;
uniform sampler2D uCurtainPolylines; // RGBA32F, row c: xyz unit vector, w arclength km
uniform vec4 uCurtainState[MAX_CURTAINS];  // peak energy flux erg cm^-2 s^-1, energy keV, point count, -
uniform float uCurtainReachKm;       // beyond this distance from its centre line no curtain emits

uniform sampler2D uFootprintMap;     // RGBA32F, nearest: curtain id, point index, distance km, other curtain
uniform vec3 uFootprintCentre;
uniform vec3 uFootprintEast;
uniform float uFootprintAngularRadius;
uniform float uFootprintSize;
uniform float uFootprintMarginKm;

int gAuroraSamples = 0; // samples this pixel's ray has taken in auroraSegment: its work (main.frag)

struct CurtainHit {
    float skipKm;   // a step this long cannot reach any curtain's emitting part
    vec3 radiance;  // linear sRGB radiance added per km of path at this point
};

// Where n projects along segment j of curtain c: (km along from the segment's start, segment
// length km, signed lateral distance km, distance beyond the segment's ends km).
vec4 segmentProjection(int c, int j, vec3 n)
{
    vec4 a = texelFetch(uCurtainPolylines, ivec2(j, c), 0);
    vec4 b = texelFetch(uCurtainPolylines, ivec2(j + 1, c), 0);
    return projectOnSegment(a.xyz, b.xyz, b.w - a.w, n, uPlanetRadiusKm);
}

// Curtain coordinates of direction n relative to curtain c, starting from polyline point i (the
// footprint map's nearest point, which can be a few texels of arclength away from the true
// nearest one): jump along the polyline by the projected along-track offset until n projects
// inside the segment, then take the closest of that segment and its neighbours.
// Returns (s km along the curtain, u km across, distance km).
vec3 curtainCoordinates(int c, int i, vec3 n)
{
    int last = int(uCurtainState[c].z) - 2; // index of the last segment
    int j = clamp(i, 0, last);
    for (int jump = 0; jump < 6; ++jump) {
        vec4 p = segmentProjection(c, j, n);
        int step = int(floor(p.x / max(p.y, 1e-6)));
        int next = clamp(j + step, 0, last);
        if (next == j)
            break;
        j = next;
    }
    vec3 best = vec3(0.0, 0.0, 1e30);
    for (int k = max(j - 1, 0); k <= min(j + 1, last); ++k) {
        vec4 p = segmentProjection(c, k, n);
        float distance = length(vec2(p.z, p.w));
        if (distance < best.z)
            best = vec3(texelFetch(uCurtainPolylines, ivec2(k, c), 0).w + clamp(p.x, 0.0, p.y), p.z, distance);
    }
    return best;
}

CurtainHit sampleCurtains(vec3 p, float h)
{
    CurtainHit hit;
    hit.radiance = vec3(0.0);
    vec3 n = normalize(p);
    float outsideKm = footprintMapOutsideKm(n, uFootprintCentre, uFootprintAngularRadius, uPlanetRadiusKm);
    if (outsideKm > 0.0) {
        // The map's cap holds every curtain with its reach (CPU side), so nothing emits out here.
        hit.skipKm = outsideKm;
        return hit;
    }
    vec2 texel = footprintMapTexel(footprintMapCoord(n, uFootprintCentre, uFootprintEast, uFootprintAngularRadius),
                                   uFootprintSize);
    vec4 nearest = texelFetch(uFootprintMap, ivec2(texel), 0);
    float lowerKm = footprintConservativeKm(nearest.z, uFootprintMarginKm);
    hit.skipKm = lowerKm - uCurtainReachKm;
    if (hit.skipKm > 0.0)
        return hit;
    // The nearest curtain, and where curtains overlap the nearest point of another one: the
    // fluxes of overlapping curtains add (the map's fourth channel, src/components/aurora/physics/footprint_map.h).
    vec4 candidates = vec4(nearest.x, nearest.y, -1.0, -1.0);
    if (nearest.w >= 0.0) {
        float second = floor(nearest.w / 65536.0);
        candidates.zw = vec2(second, nearest.w - 65536.0 * second);
    }
    for (int k = 0; k < 2; ++k) {
        vec2 candidate = k == 0 ? candidates.xy : candidates.zw;
        if (candidate.x < 0.0)
            continue;
        int c = int(candidate.x);
        vec3 su = curtainCoordinates(c, int(candidate.y), n);
        if (su.z > uCurtainReachKm)
            continue;
        float flux = uCurtainState[c].x * curtainProfile(c, su.x, su.y);
        if (flux > 0.0)
            hit.radiance += flux * auroraEmissionRgbPerKm(h, uCurtainState[c].y);
    }
    return hit;
}

// Emission integrated along the ray segment [seg.x, seg.y] by the left-endpoint rectangle rule on the
// grid t_k = seg.x + k·uAuroraStepKm (the last step ends at seg.y). With skipping, long jumps where the
// footprint map proves no curtain is near (moving s km changes the footprint position by at most s km
// above the ground) go over whole steps only, landing on the same grid: the skipping march evaluates a
// subset of the naive march's samples, and every sample it leaves out emits nothing, so both give the
// same sum (tests/render/skipping_test.cpp).
vec3 auroraSegment(vec3 o, vec3 d, vec2 seg)
{
    vec3 sum = vec3(0.0);
    // The bound only guards against a NaN or absurd segment (4e6 steps is beyond any ray through the shell).
    int steps = int(min(ceil((seg.y - seg.x) / uAuroraStepKm), 4.0e6));
    for (int k = 0; k < steps;) {
        float t = seg.x + float(k) * uAuroraStepKm;
        vec3 p = o + t * d;
        float h = length(p) - uPlanetRadiusKm;
        CurtainHit hit = sampleCurtains(p, h);
        ++gAuroraSamples;
        sum += hit.radiance * min(uAuroraStepKm, seg.y - t);
        k += uSkipEmptySpace != 0 ? int(clamp(floor(hit.skipKm / uAuroraStepKm), 1.0, 4.0e6)) : 1;
    }
    return sum;
}

// The aurora shell between uAuroraBottomKm and uAuroraTopKm: a ray may cross it twice (in front
// of the planet's limb and behind it); each part is seen through the lower atmosphere if it lies
// behind it.
Ray shadeAurora(Ray ray)
{
    ShellSegments shell = rayShell(ray.origin, ray.direction, uPlanetRadiusKm + uAuroraBottomKm,
                                   ray.altitude - uAuroraBottomKm, uPlanetRadiusKm + uAuroraTopKm,
                                   ray.altitude - uAuroraTopKm, ray.end);
    if (shell.first.x < shell.first.y)
        ray.radiance += auroraSegment(ray.origin, ray.direction, shell.first) * transmittanceTo(ray, shell.first);
    if (shell.second.x < shell.second.y)
        ray.radiance += auroraSegment(ray.origin, ray.direction, shell.second) * transmittanceTo(ray, shell.second);
    return ray;
}
