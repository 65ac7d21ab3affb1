// The glory's phase table on the GPU, in float: the sum over a wavelength's radius nodes of
// weight · S11(θ) for a non-absorbing sphere (m = n real, as water in the visible), in two passes run
// one after the other for each wavelength (MIE_TABLE_PASS 1, then 2). The normalisation by the
// size-averaged scattering cross-section is left to the caller.
//
// Pass 1, one invocation per radius node: the Mie coefficients aₙ, bₙ (Bohren & Huffman 1983, eq. 4.88;
// Wiscombe 1980, Appl. Opt. 19, 1505) and the scattering efficiency Qsca = (2/x²) Σ (2n+1)(|aₙ|² + |bₙ|²).
// Pass 2, one invocation per angle and chunk of nodes: S1, S2 from the coefficients with πₙ, τₙ by upward
// recurrence in μ = cos θ (Bohren & Huffman eq. 4.47), summed over the chunk's nodes with their weights.
// The caller adds the chunks.
layout(local_size_x = 64) in;

// One radius node of the size quadrature. The starts of the recurrences come from the caller in double,
// rounded once to float: sin x and cos x (GLSL leaves the precision of sin to the driver, and x reaches
// ~300) and Dₙ(mx) at the downward recurrence's start index (Lentz's continued fraction, as the CPU
// table; started from 0 instead, the single-size table at x ≈ 300 was 5 % off).
struct Node {
    float x;      // size parameter 2πr/λ
    float weight; // trapezoid weight × n(r), 1 for a single size
    float sinX;
    float cosX;
    int terms;                   // Wiscombe's number of terms N
    int startIndex;              // max(N, ⌈mx⌉) + 15
    float startLogDerivative;    // D at startIndex
    int unused;
};

layout(std430, binding = 0) readonly buffer Nodes { Node nodes[]; };
// Term n of node j of the current wavelength at [j · uTermStride + n − 1]: (Re aₙ, Im aₙ, Re bₙ, Im bₙ)
// times (2n+1)/(n(n+1)), the factor of S1 and S2. Pass 1 first keeps Dₙ(mx) in the x component.
layout(std430, binding = 1) buffer Coefficients { vec4 coefficients[]; };
layout(std430, binding = 2) buffer Efficiencies { float scatteringEfficiencies[]; }; // per node
// Per angle μ = cos θ as σ(1 − s), σ = ±1 the nearer end and s = 1 − σμ ≥ 0 from the caller in double:
// μ itself rounded to float near ±1 would move the angle (by 0.002° at 0.1° from the antisolar point,
// where the glory's rings are).
layout(std430, binding = 3) readonly buffer Cosines { vec2 cosines[]; };
layout(std430, binding = 4) buffer Sums { float s11Sums[]; }; // [(uFirstChunk + chunk) · uAngleCount + angle]

uniform int uFirstNode; // the current wavelength's first node
uniform int uNodeCount;
uniform int uTermStride;
uniform float uIndex; // water's refractive index at the current wavelength
uniform int uAngleCount;
uniform int uChunkNodes;  // nodes per chunk of pass 2
uniform int uFirstChunk; // the current wavelength's first chunk

// p / (p + iq) for real p, q, both scaled by max(|p|, |q|) so that |p + iq|² cannot overflow.
vec2 overZeta(float p, float q)
{
    float s = max(abs(p), abs(q));
    p /= s;
    q /= s;
    return p * vec2(p, -q) / (p * p + q * q);
}

void coefficientsOfNode(int j)
{
    Node node = nodes[uFirstNode + j];
    int base = j * uTermStride;
    float z = uIndex * node.x;
    // Dₙ(z) by downward recurrence Dₙ₋₁ = n/z − 1/(Dₙ + n/z), stable for every z.
    float d = node.startLogDerivative;
    for (int n = node.startIndex; n > 0; --n) {
        if (n <= node.terms)
            coefficients[base + n - 1].x = d;
        float nOverZ = float(n) / z;
        d = nOverZ - 1.0 / (d + nOverZ);
    }
    // ψₙ = x jₙ(x), χₙ = −x yₙ(x) by upward recurrence fₙ₊₁ = (2n+1)/x fₙ − fₙ₋₁ from ψ₋₁ = cos x,
    // ψ₀ = sin x, χ₋₁ = −sin x, χ₀ = cos x. Beyond n ≈ x ψₙ's recurrence is unstable, but its error
    // grows as χₙ does and enters aₙ, bₙ divided by ζₙ = ψₙ + iχₙ: an absolute error of float's order.
    float psiPrevious = node.cosX, psi = node.sinX;
    float chiPrevious = -node.sinX, chi = node.cosX;
    float sum = 0.0;
    for (int n = 1; n <= node.terms; ++n) {
        float f = float(2 * n - 1) / node.x;
        float psiNext = f * psi - psiPrevious;
        float chiNext = f * chi - chiPrevious;
        psiPrevious = psi;
        psi = psiNext;
        chiPrevious = chi;
        chi = chiNext;
        float dn = coefficients[base + n - 1].x;
        float ta = dn / uIndex + float(n) / node.x;
        float tb = uIndex * dn + float(n) / node.x;
        // aₙ = (ta ψₙ − ψₙ₋₁) / (ta ζₙ − ζₙ₋₁), bₙ the same with tb; the numerators are real for real m.
        vec2 a = overZeta(ta * psi - psiPrevious, ta * chi - chiPrevious);
        vec2 b = overZeta(tb * psi - psiPrevious, tb * chi - chiPrevious);
        sum += float(2 * n + 1) * (dot(a, a) + dot(b, b));
        coefficients[base + n - 1] = float(2 * n + 1) / float(n * (n + 1)) * vec4(a, b);
    }
    scatteringEfficiencies[uFirstNode + j] = 2.0 * sum / (node.x * node.x);
}

// Σ weight · S11 at one angle over one chunk of uChunkNodes nodes. Chunks keep each invocation's loops
// short: llvmpipe stops a shader's loop after 65535 iterations in all (nodes × terms of a whole row
// exceed it).
void s11OfAngle(int angle, int chunk)
{
    float sigma = cosines[angle].x, s = cosines[angle].y;
    float total = 0.0;
    for (int j = chunk * uChunkNodes; j < min(uNodeCount, (chunk + 1) * uChunkNodes); ++j) {
        Node node = nodes[uFirstNode + j];
        if (node.weight == 0.0)
            continue;
        vec2 s1 = vec2(0.0), s2 = vec2(0.0);
        float piPrevious = 0.0, pi = 1.0; // π₀, π₁
        for (int n = 1; n <= node.terms; ++n) {
            float muPi = sigma * (pi - s * pi); // μ πₙ
            float tau = float(n) * muPi - float(n + 1) * piPrevious;
            vec4 c = coefficients[j * uTermStride + n - 1];
            s1 += c.xy * pi + c.zw * tau;
            s2 += c.xy * tau + c.zw * pi;
            float piNext = (float(2 * n + 1) * muPi - float(n + 1) * piPrevious) / float(n);
            piPrevious = pi;
            pi = piNext;
        }
        total += node.weight * 0.5 * (dot(s1, s1) + dot(s2, s2));
    }
    s11Sums[(uFirstChunk + chunk) * uAngleCount + angle] = total;
}

void main()
{
    int i = int(DISPATCH_INVOCATION.x);
#if MIE_TABLE_PASS == 1
    if (i < uNodeCount)
        coefficientsOfNode(i);
#else
    if (i < uAngleCount)
        s11OfAngle(i, int(DISPATCH_INVOCATION.y));
#endif
}
