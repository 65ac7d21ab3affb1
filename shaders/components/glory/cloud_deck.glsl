// The cloud deck: a layer of water drops between the spheres R + base and R + top about the planet's
// centre, optical thickness tau, asymmetry g of its drops. Shared by the shader and the C++ reference
// (src/common/glsl.h); needs render/ray_sphere.glsl.

// Where the ray from a camera `altitude` km above the ground first meets the deck: the top seen from
// above, the base seen from below, 0 from inside; negative when it never does. A camera on the top (or
// the base) is outside: looking away from the deck it sees none, looking into it meets it at 0.
real cloudDeckHit(vec3 o, vec3 d, real R, real altitude, real baseKm, real topKm)
{
    if (altitude >= topKm) {
        vec2 top = raySphere(o, d, R + topKm, altitude - topKm);
        return top.x <= top.y ? top.x : real(-1.0);
    }
    if (altitude <= baseKm) {
        vec2 base = raySphere(o, d, R + baseKm, altitude - baseKm);
        return base.x <= base.y ? base.y : real(-1.0);
    }
    return real(0.0);
}

// Single scattering by a plane-parallel layer of optical thickness tau lit by a parallel beam of
// irradiance E (Chandrasekhar 1960, Radiative Transfer, ch. 1; Hansen & Travis 1974, eq. 2.42 for
// the first order): the reflected radiance is E P(Theta)/(4 pi) times this factor, mu0 the cosine of
// the light's zenith angle and mu the viewer's, both > 0. No absorption (the drops do not absorb).
real singleScatteringFactor(real mu0, real mu, real tau)
{
    return mu0 / (mu0 + mu) * (real(1.0) - exp(-tau * (real(1.0) / mu0 + real(1.0) / mu)));
}

// The layer's reflectance in the two-stream approximation for conservative scattering (Bohren 1987,
// "Multiple scattering of light and some of its observable consequences", Am. J. Phys. 55, 524):
// R = (1 - g) tau / (2 + (1 - g) tau); its transmittance is 1 - R.
real twoStreamReflectance(real tau, real g)
{
    real x = (real(1.0) - g) * tau;
    return x / (real(2.0) + x);
}

// The deck's diffuse light (cd/m^2 per lux of light on a surface facing it): seen from above, the
// two-stream reflectance as a Lambertian surface (it holds the first order too, so it slightly
// overstates the background under the glory); from below, the transmittance; from inside, their mean.
real cloudDeckDiffuse(real mu0, real tau, real g, bool fromAbove, bool fromBelow)
{
    real r = twoStreamReflectance(tau, g);
    real lambert = max(mu0, real(0.0)) / kPi;
    if (fromAbove)
        return lambert * r;
    if (fromBelow)
        return lambert * (real(1.0) - r);
    return lambert * real(0.5);
}
