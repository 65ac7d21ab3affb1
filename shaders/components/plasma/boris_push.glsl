// The leapfrog push of one particle (shared by the compute shaders and the C++ simulation,
// src/common/glsl.h). Velocities live at half steps, positions at whole steps.

// v(n+1/2) from v(n−1/2) in the fields at step n: Boris (1970), as in Birdsall & Langdon (1991) §4-4:
// half an electric kick, a rotation about B, the other half kick. The rotation uses
// t = (q B/m)(Δt/2) and s = 2t/(1 + t²); it turns the velocity by exactly 2·atan(ω_c Δt/2)
// (ω_c = |q B|/m) and keeps its magnitude, for any Δt.
// velocity (m/s), electricField (V/m), magneticField (T), chargeOverMass (C/kg), dt (s).
vec3 borisVelocity(vec3 velocity, vec3 electricField, vec3 magneticField, real chargeOverMass, real dt)
{
    vec3 halfKick = electricField * (chargeOverMass * real(0.5) * dt);
    vec3 t = magneticField * (chargeOverMass * real(0.5) * dt);
    vec3 s = t * (real(2.0) / (real(1.0) + dot(t, t)));
    vec3 vMinus = velocity + halfKick;
    vec3 vPrime = vMinus + cross(vMinus, t);
    vec3 vPlus = vMinus + cross(vPrime, s);
    return vPlus + halfKick;
}

// x(n+1) = x(n) + v(n+1/2) Δt, brought back into the periodic box [0, boxLength) per axis (m).
vec3 leapfrogPosition(vec3 position, vec3 velocity, real dt, vec3 boxLength)
{
    vec3 moved = position + velocity * dt;
    return moved - boxLength * floor(moved / boxLength);
}
