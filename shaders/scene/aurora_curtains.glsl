// Aurora curtains: an emissive shell between uAuroraBottomKm and uAuroraTopKm. A curtain's
// footprint is a polyline of great-circle arcs on the sphere (control points as unit vectors),
// displaced sideways by travelling folds; the precipitating energy flux falls off as a Gaussian
// across the curtain. The emission at a point is that flux times the tabulated line emission of
// the curtain's electrons at that altitude (aurora/deposition.glsl: Lazarev deposition, line
// yields, CIE colour), so the curtain's height and colours follow from its electron energy.
const int MAX_CURTAINS = 16;
const int MAX_CURTAIN_POINTS = 256;
uniform float uAuroraBottomKm;
uniform float uAuroraTopKm;
uniform float uAuroraStepKm;
uniform int uCurtainCount;
uniform vec4 uCurtainPoints[MAX_CURTAIN_POINTS]; // xyz: unit vector; w: arclength from the first point, km
uniform vec2 uCurtainRange[MAX_CURTAINS];       // first point, point count (integers)
uniform vec4 uCurtainShape[MAX_CURTAINS];       // energy flux erg cm^-2 s^-1, half-thickness km, energy keV, fold amplitude km
uniform vec2 uCurtainFold[MAX_CURTAINS];        // fold wavenumber rad/km, fold phase rad (from double time on the CPU)

struct CurtainHit {
    float skipKm;   // a step this long cannot reach any curtain's visible core
    vec3 radiance;  // linear sRGB radiance added per km of path at this point
};

CurtainHit sampleCurtains(vec3 p, float h)
{
    CurtainHit hit;
    hit.skipKm = 1e9;
    hit.radiance = vec3(0.0);
    vec3 n = normalize(p);
    float R = uPlanetRadiusKm;
    for (int c = 0; c < uCurtainCount; ++c) {
        vec4 shape = uCurtainShape[c];
        float nearestKm = 1e9; // lower bound of the distance to the displaced curtain
        float flux = 0.0;
        int first = int(uCurtainRange[c].x), last = first + int(uCurtainRange[c].y) - 1;
        for (int i = first; i < last; ++i) {
            vec3 a = uCurtainPoints[i].xyz;
            vec3 b = uCurtainPoints[i + 1].xyz;
            vec3 normal = normalize(cross(a, b));
            float along = atan(dot(cross(a, n), normal), dot(a, n)); // angle from a along the arc
            float arc = (uCurtainPoints[i + 1].w - uCurtainPoints[i].w) / R;
            float distKm;
            float lowerKm;
            if (along < 0.0 || along > arc) {
                vec3 end = along < 0.0 ? a : b;
                distKm = R * acos(clamp(dot(n, end), -1.0, 1.0));
                lowerKm = max(distKm - shape.w, 0.0);
            } else {
                float s = uCurtainPoints[i].w + along * R;
                float lateral = R * asin(clamp(dot(n, normal), -1.0, 1.0));
                float fold = shape.w * sin(uCurtainFold[c].x * s + uCurtainFold[c].y);
                distKm = abs(lateral - fold);
                lowerKm = max(abs(lateral) - shape.w, 0.0);
            }
            nearestKm = min(nearestKm, lowerKm);
            float x = distKm / shape.y;
            flux = max(flux, exp(-x * x));
        }
        hit.skipKm = min(hit.skipKm, nearestKm - 3.0 * shape.y);
        if (flux > 1e-12)
            hit.radiance += shape.x * flux * auroraEmissionRgbPerKm(h, shape.z);
    }
    return hit;
}

// Emission integrated along the ray segment [seg.x, seg.y]: fine steps near curtains, long
// steps where the footprint distance proves no curtain is near (moving s km changes the
// footprint position by at most s km above the ground).
vec3 auroraSegment(vec3 o, vec3 d, vec2 seg)
{
    vec3 sum = vec3(0.0);
    float t = seg.x;
    for (int i = 0; i < 4096 && t < seg.y; ++i) {
        vec3 p = o + t * d;
        float h = length(p) - uPlanetRadiusKm;
        CurtainHit hit = sampleCurtains(p, h);
        float dt = min(max(uAuroraStepKm, hit.skipKm), seg.y - t);
        sum += hit.radiance * dt;
        t += dt;
    }
    return sum;
}
