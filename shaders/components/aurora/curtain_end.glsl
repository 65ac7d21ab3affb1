// The end of a curtain (docs/aurora-physics.md, "Curtains"). One text for GLSL and C++ (src/common/glsl.h).
//
// Beyond either end the curtain keeps its end's column and fades with the distance e beyond it as a
// Gaussian that reaches e^-8 at the curtain's reach: the smooth profile's own fall-off across it (reach =
// 4σ), so that a smooth curtain ends in a round cap, exp(−(u² + e²) / 2σ²), and a detailed one fades over
// the same distance, with no edge where its reach cuts it off (3.4e-4 of the column there).
real curtainEndFade(real beyondEndKm, real reachKm)
{
    real x = beyondEndKm / reachKm;
    return exp(real(-8.0) * x * x);
}

// The most a run of a curtain's march moves beyond its end: σ/4 (reach / 16), over which the fade is nearly
// linear, so that evaluating it at the run's flux-weighted mean position errs by at most (1/4)² / 8 of the
// column (|d²fade/de²| <= 1/σ²), 0.8%.
real curtainEndFadeStepKm(real reachKm)
{
    return reachKm / real(16.0);
}
