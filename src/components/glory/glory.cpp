#include "physics/constants.h"
#include "components/glory/glory.h"

#include "common/formatted.h"
#include "components/glory/mie/mie_coefficients.h"
#include "components/glory/mie/mie_scattering.h"
#include "components/glory/optics/water.h"
#include "components/roles/lower_atmosphere.h"
#include "components/roles/names.h"
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "io/table_cache.h"
#include "physics/atmosphere/airmass_exact.h"
#include "physics/colour_matching.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace aurorawall::components::glory {


namespace f64 {
using namespace aurorawall::scene::f64;
#include "physics/constants.glsl"
#include "components/glory/cloud_deck.glsl"
#include "components/glory/glory_angle.glsl"
#include "render/angle.glsl"
#include "physics/colour.glsl"
} // namespace f64

namespace {

constexpr int kSampleTexels = 1024; // the per-pixel wavelength table over u in [0, 1]

// The light's illuminance per linear-sRGB primary (lux): the XYZ of its spectrum, 683 ∫ E cmf dλ.
glm::dvec3 lightRgb(const optics::LightSource& light)
{
    const optics::LightSpectrum spectrum = light.spectrum();
    glm::dvec3 xyz(0.0);
    for (double nm = physics::kCieFirstNm; nm <= physics::kCieLastNm; nm += 1.0)
        xyz += ((nm == physics::kCieFirstNm || nm == physics::kCieLastNm) ? 0.5 : 1.0) * spectrum(nm) *
               physics::colourMatching(nm);
    return f64::desaturateIntoGamut(f64::xyzToLinearSrgb(xyz * physics::kLumensPerWatt));
}

std::string tableKey(const Settings& s)
{
    const optics::GloryTableSpec& t = s.table;
    char text[512];
    std::snprintf(text, sizeof text,
                  "glory phase table v2; drops %a um variance %a; angles %a rad x %d + %d + %a rad x %d; wavelengths %d from %a "
                  "to %a nm; size parameter step %a; disc radius %a rad; executable %s",
                  s.effectiveRadiusUm, s.effectiveVariance, t.angles.glorySpanRad, t.angles.gloryCount,
                  t.angles.middleCount, t.angles.forwardSpanRad, t.angles.forwardCount, t.wavelengthCount, t.firstNm, t.lastNm, t.sizeParameterStep,
                  s.light.discRadiusRad(), io::executableDigest().c_str());
    return text;
}

std::vector<char> bytesOf(const optics::PhaseTable& table)
{
    std::vector<char> bytes(sizeof(long long) + table.values.size() * sizeof(double));
    std::memcpy(bytes.data(), &table.mieSeries, sizeof(long long));
    std::memcpy(bytes.data() + sizeof(long long), table.values.data(), table.values.size() * sizeof(double));
    return bytes;
}

std::vector<float> floats(const std::vector<glm::dvec3>& v)
{
    std::vector<float> out;
    for (const glm::dvec3& c : v)
        out.insert(out.end(), {float(c.r), float(c.g), float(c.b)});
    return out;
}

// The per-pixel wavelength samples over u in [0, 1]: the wavelength (as the phase texture's
// coordinate) and the weight 683 E(λ) cmf(λ) / (4π pdf(λ)) of the wavelength drawn at u, for a pdf
// uniform over the table's wavelengths, or proportional to E(λ) (x̄ + ȳ + z̄)(λ) (the inverse of its
// cumulative distribution, linear between the table's wavelengths).
std::vector<float> wavelengthSamples(const optics::PhaseTable& table, const optics::LightSource& light, bool importance)
{
    const optics::LightSpectrum spectrum = light.spectrum();
    const std::vector<double>& nm = table.wavelengthsNm;
    const size_t count = nm.size();
    const double first = nm.front(), last = nm.back(), range = last - first;
    std::vector<double> density(count), cumulative(count, 0.0);
    for (size_t w = 0; w < count; ++w) {
        const glm::dvec3 cmf = physics::colourMatching(nm[w]);
        density[w] = importance ? spectrum(nm[w]) * (cmf.x + cmf.y + cmf.z) : 1.0;
        if (w > 0)
            cumulative[w] = cumulative[w - 1] + 0.5 * (density[w] + density[w - 1]) * (nm[w] - nm[w - 1]);
    }
    const double total = cumulative.back();
    std::vector<float> texels;
    size_t w = 0;
    for (int i = 0; i < kSampleTexels; ++i) {
        const double target = total * (i + 0.5) / kSampleTexels;
        while (w + 2 < count && cumulative[w + 1] < target)
            ++w;
        // Within [nm[w], nm[w+1]] the density a + b s is linear: its cumulative a s + b s²/2 = need, solved
        // in the form without cancellation, s = 2 need / (a + √(a² + 2 b need)) (also for b = 0).
        const double h = nm[w + 1] - nm[w], a = density[w], b = (density[w + 1] - density[w]) / h;
        const double need = target - cumulative[w];
        const double s = 2.0 * need / (a + std::sqrt(std::max(a * a + 2.0 * b * need, 0.0)));
        const double lambda = std::clamp(nm[w] + s, first, last);
        const double pdf = (a + b * (lambda - nm[w])) / total;
        const glm::dvec3 weight = physics::kLumensPerWatt * spectrum(lambda) *
                                  physics::colourMatching(lambda) / (4.0 * physics::kPi * pdf);
        const double coordinate = ((lambda - first) / range * double(count - 1) + 0.5) / double(count);
        texels.insert(texels.end(), {float(coordinate), float(weight.x), float(weight.y), float(weight.z)});
    }
    return texels;
}

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s)
        : s_(s), colour_(gl::Texture::create2D(1, 1, gl::TexelFormat::RGB32F, gl::Filter::Linear, gl::Wrap::Clamp)),
          phase_(gl::Texture::create2D(1, 1, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Clamp)),
          samples_(gl::Texture::create2D(1, 1, gl::TexelFormat::RGBA32F, gl::Filter::Linear, gl::Wrap::Clamp))
    {
        const GloryTables tables = gloryTables(s);
        const optics::PhaseTable& table = tables.phase;
        const int angles = table.angles.size();
        colour_ = gl::Texture::create2D(angles, 1, gl::TexelFormat::RGB32F, gl::Filter::Linear, gl::Wrap::Clamp);
        colour_.upload(floats(optics::gloryLinearSrgb(optics::gloryXyz(table, s.light))));
        if (s.sampling != WavelengthSampling::ColourTable) {
            phase_ = gl::Texture::create2D(angles, int(table.wavelengthsNm.size()), gl::TexelFormat::R32F,
                                           gl::Filter::Linear, gl::Wrap::Clamp);
            phase_.upload(std::vector<float>(table.values.begin(), table.values.end()));
            samples_ = gl::Texture::create2D(kSampleTexels, 1, gl::TexelFormat::RGBA32F, gl::Filter::Linear, gl::Wrap::Clamp);
            samples_.upload(wavelengthSamples(table, s.light, s.sampling == WavelengthSampling::Importance));
        }
        lightRgb_ = lightRgb(s.light);
        asymmetry_ = deckAsymmetry(s);
        log_ = common::formatted("glory table %d angles x %zu wavelengths (%lld Mie series): %.0f ms, %s", angles,
                                 table.wavelengthsNm.size(), table.mieSeries, tables.seconds * 1e3,
                                 tables.outcome.c_str());
    }
    std::string precomputationLog() const override { return log_; }
    void setFrame(gl::Program& program, const cluster::FrameState&) override
    {
        const optics::AngleGrid& g = s_.table.angles;
        program.set("uDeckBaseKm", float(s_.deckTopKm - s_.deckThicknessKm));
        program.set("uDeckTopKm", float(s_.deckTopKm));
        program.set("uDeckOpticalThickness", float(s_.opticalThickness));
        program.set("uDeckAsymmetry", float(asymmetry_));
        program.set("uGloryLightDirection", glm::vec3(s_.lightDirection));
        program.set("uGloryLightRgb", glm::vec3(lightRgb_));
        program.set("uGloryAngleSpans", glm::vec3(float(g.glorySpanRad), float(physics::kPi - g.glorySpanRad - g.forwardSpanRad),
                                                  float(g.forwardSpanRad)));
        program.set("uGloryAngleCounts", glm::vec3(float(g.gloryCount), float(g.middleCount), float(g.forwardCount)));
        program.set("uGlorySampling", static_cast<int>(s_.sampling));
        program.set("uGloryWavelengthsPerPixel", s_.wavelengthsPerPixel);
    }
    void bind(gl::Program& program) const override
    {
        program.bindTexture("uGloryColour", 6, colour_.id());
        program.bindTexture("uGloryPhase", 7, phase_.id());
        program.bindTexture("uGlorySamples", 8, samples_.id());
    }

private:
    const Settings& s_;
    gl::Texture colour_, phase_, samples_;
    glm::dvec3 lightRgb_{0.0};
    double asymmetry_ = 0.0;
    std::string log_;
};

// The double-precision model of glory.glsl, its colour from a finer table: twice the angles, every
// 5 nm, half the size-parameter step (docs/GLORY.md gives its own convergence).
class Reference : public scene::ReferenceShader {
public:
    Reference(const Settings& s, const scene::Scene& scene)
        : s_(s), radiusKm_(scene.planetRadiusKm), asymmetry_(deckAsymmetry(s)), lightRgb_(lightRgb(s.light))
    {
        Settings fine = s;
        fine.table = referenceTableSpec(s.table);
        const GloryTables tables = gloryTables(fine);
        grid_ = tables.phase.angles;
        colour_ = optics::gloryLinearSrgb(optics::gloryXyz(tables.phase, s.light));
        if (const auto air = roles::lowerAir(scene)) {
            air_ = {air->topKm, air->scaleHeightKm};
            extinctionPerKm_ = air->extinctionPerKm;
        }
    }
    f64::Ray bound(f64::Ray ray) const override
    {
        const double t = hit(ray);
        if (t >= 0.0 && t < ray.end) {
            ray.end = t;
            ray.groundT = -1.0;
        }
        return ray;
    }
    f64::Ray shade(f64::Ray ray) const override
    {
        const double t = hit(ray);
        if (t < 0.0 || t != ray.end)
            return ray;
        const glm::dvec3 p = ray.origin + t * ray.direction, up = glm::normalize(p);
        const double mu0 = glm::dot(up, s_.lightDirection);
        if (mu0 <= 0.0)
            return ray;
        const double base = s_.deckTopKm - s_.deckThicknessKm;
        const bool above = ray.altitude >= s_.deckTopKm, below = ray.altitude <= base;
        const double altitude = above ? s_.deckTopKm : (below ? base : ray.altitude);
        glm::dvec3 deck = lightRgb_ * f64::cloudDeckDiffuse(mu0, s_.opticalThickness, asymmetry_, above, below);
        if (above) {
            const double mu = std::max(-glm::dot(up, ray.direction), 1e-6);
            const double gamma = f64::angleBetween(ray.direction, -s_.lightDirection);
            deck += optics::colourAtAngle(grid_, colour_, gamma) * f64::singleScatteringFactor(mu0, mu, s_.opticalThickness);
        }
        ray.radiance += deck * lightTransmittance(p, altitude) * ray.transmittance;
        return ray;
    }

private:
    double hit(const f64::Ray& ray) const
    {
        return f64::cloudDeckHit(ray.origin, ray.direction, radiusKm_, ray.altitude, s_.deckTopKm - s_.deckThicknessKm,
                                 s_.deckTopKm);
    }
    glm::dvec3 lightTransmittance(glm::dvec3 p, double altitude) const
    {
        if (air_.x <= 0.0)
            return glm::dvec3(1.0);
        const glm::dvec2 top = f64::raySphere(p, s_.lightDirection, radiusKm_ + air_.x, altitude - air_.x);
        const double airmass = physics::atmosphere::exactAirmass(p, s_.lightDirection, 0.0, std::max(top.y, 0.0), air_.y, radiusKm_);
        return glm::exp(-extinctionPerKm_ * airmass);
    }

    const Settings& s_;
    double radiusKm_;
    double asymmetry_;
    glm::dvec3 lightRgb_;
    optics::AngleGrid grid_;
    std::vector<glm::dvec3> colour_;
    glm::dvec2 air_{0.0};              // the lower atmosphere's top and scale height (km); top 0: none
    glm::dvec3 extinctionPerKm_{0.0};
};

void readLight(const config::TableReader& t, Settings& s)
{
    s.light.body = static_cast<optics::LightSource::Body>(t.choice("body", {"sun", "moon"}, int(s.light.body)));
    const bool moon = s.light.body == optics::LightSource::Body::Moon;
    s.light.angularDiameterDeg = t.number("angular_diameter_deg", 0.0, 5.0, moon ? 0.518 : 0.533);
    s.light.sunIlluminanceLux = t.number("sun_illuminance_lux", 0.0, 1e7, s.light.sunIlluminanceLux);
    s.light.sunTemperatureK = t.number("sun_temperature_k", 1000.0, 50000.0, s.light.sunTemperatureK);
    if (moon) {
        s.light.moonGeometricAlbedo = t.numberAbove("albedo", 0.0, 1.0, s.light.moonGeometricAlbedo);
        s.light.moonPhaseAngleDeg = t.number("phase_angle_deg", 0.0, 180.0, s.light.moonPhaseAngleDeg);
    }
    s.lightGiven = true;
    s.lightDirection = scene::directionInSky(t.number("site_latitude_deg", -90, 90), t.number("site_longitude_deg", -360, 360),
                                             t.number("elevation_deg", -90, 90), t.number("azimuth_deg", -360, 360));
    t.rejectUnknownKeys();
}

// The most work a glory table may take (optics::phaseTableWork): 70 times the default's 7.1e9, which
// builds in 8 s on the 2-core machine, so about 10 minutes there; wide distributions of large drops
// reach far beyond (effective_radius_um 50 with effective_variance 0.3: 6.6e12, hours).
constexpr double kMaxTableWork = 5e11;

void refuseTableBeyondBudget(const config::TableReader& t, const Settings& s)
{
    const mie::DropSizeDistribution drops = s.drops();
    const double work = optics::phaseTableWork(drops, s.table);
    if (work > kMaxTableWork)
        t.fail("effective_variance",
               common::formatted("the glory table would sum %.2g Mie terms times angles (drops up to %.0f um), more "
                                 "than the %.0e (about 10 minutes on 2 cores) a table may take: lower "
                                 "effective_radius_um or effective_variance, raise size_parameter_step, or lower "
                                 "table_wavelengths or the angle counts",
                                 work, drops.radiusRangeUm().second, kMaxTableWork));
}

class Glory : public scene::ComponentWithRenderer<Settings, Renderer> {
public:
    std::vector<std::string> needs() const override { return {roles::kGround}; }
    void read(const config::TableReader& t, scene::Scene& scene, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        s.deckTopKm = t.numberAbove("deck_top_km", 0.0, 50.0, s.deckTopKm);
        s.deckThicknessKm = t.numberAbove("deck_thickness_km", 0.0, 50.0, s.deckThicknessKm);
        if (s.deckThicknessKm > s.deckTopKm)
            t.fail("deck_thickness_km", "the deck's base (deck_top_km - deck_thickness_km) must not be below the ground");
        if (const auto air = roles::lowerAir(scene); air && s.deckTopKm >= air->topKm)
            t.fail("deck_top_km", "the deck must lie below " + air->topKey);
        s.opticalThickness = t.numberAbove("optical_thickness", 0.0, 1000.0, s.opticalThickness);
        s.effectiveRadiusUm = t.number("effective_radius_um", 0.5, 50.0, s.effectiveRadiusUm);
        s.effectiveVariance = t.number("effective_variance", 0.0, 0.3, s.effectiveVariance);
        optics::GloryTableSpec& table = s.table;
        table.angles.glorySpanRad = t.number("glory_span_deg", 1.0, 90.0, table.angles.glorySpanRad * 180.0 / physics::kPi) * physics::kPi / 180.0;
        table.angles.gloryCount = t.integer("glory_angles", 16, 8001, table.angles.gloryCount);
        table.angles.middleCount = t.integer("middle_angles", 16, 4000, table.angles.middleCount);
        table.angles.forwardSpanRad =
            t.number("forward_span_deg", 1.0, 90.0, table.angles.forwardSpanRad * 180.0 / physics::kPi) * physics::kPi / 180.0;
        table.angles.forwardCount = t.integer("forward_angles", 16, 8000, table.angles.forwardCount);
        if (table.angles.glorySpanRad + table.angles.forwardSpanRad > 0.9 * physics::kPi)
            t.fail("forward_span_deg", "glory_span_deg + forward_span_deg must leave at least 18 degrees between them");
        table.wavelengthCount = t.integer("table_wavelengths", 2, 401, table.wavelengthCount);
        table.sizeParameterStep = t.number("size_parameter_step", 0.005, 2.0, table.sizeParameterStep);
        refuseTableBeyondBudget(t, s);
        s.sampling = static_cast<WavelengthSampling>(
            t.choice("wavelength_sampling", {"colour-table", "uniform", "importance"}, int(s.sampling)));
        s.wavelengthsPerPixel = t.integer("wavelengths_per_pixel", 1, 256, s.wavelengthsPerPixel);
        if (t.has("light"))
            readLight(t.table("light"), s);
        else if (!s.lightGiven)
            t.fail("light", "missing: the [glory.light] table (body, site_latitude_deg, site_longitude_deg, elevation_deg, azimuth_deg)");
        t.rejectUnknownKeys();
    }
    std::vector<std::string> shaderModules() const override
    {
        return {"render/angle.glsl", "physics/colour.glsl", "components/glory/glory_angle.glsl",
                "components/glory/cloud_deck.glsl", "components/glory/glory.glsl"};
    }
    std::string shaderGeometryCall() const override { return "boundByCloudDeck(ray)"; }
    std::string shaderShadeCall() const override { return "shadeGlory(ray)"; }
    scene::Shell shell() const override { return scene::Shell::CloudDeck; }
    double reachKm(const scene::Scene& scene) const override { return scene.settings<Settings>().deckTopKm; }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext&) const override
    {
        return std::make_unique<Reference>(scene.settings<Settings>(), scene);
    }
};

} // namespace

mie::DropSizeDistribution Settings::drops() const
{
    return effectiveVariance > 0.0 ? mie::DropSizeDistribution::gamma(effectiveRadiusUm, effectiveVariance)
                                   : mie::DropSizeDistribution::singleSize(effectiveRadiusUm);
}

optics::GloryTableSpec referenceTableSpec(const optics::GloryTableSpec& spec)
{
    optics::GloryTableSpec fine = spec;
    fine.angles.gloryCount = 2 * spec.angles.gloryCount - 1;
    fine.angles.middleCount = 2 * spec.angles.middleCount;
    fine.angles.forwardCount = 2 * spec.angles.forwardCount;
    fine.wavelengthCount = 81;
    fine.firstNm = physics::kCieFirstNm;
    fine.lastNm = physics::kCieLastNm;
    fine.sizeParameterStep = 0.5 * spec.sizeParameterStep;
    return fine;
}

GloryTables gloryTables(const Settings& s)
{
    const auto start = std::chrono::steady_clock::now();
    GloryTables tables;
    tables.phase = optics::emptyPhaseTable(s.table);
    const io::CachedTable cached = io::cachedTable(io::defaultCacheDirectory(), "glory", tableKey(s), [&] {
        return bytesOf(optics::smearedByDisc(optics::phaseTable(s.drops(), s.table), s.light.discRadiusRad()));
    });
    if (cached.bytes.size() != sizeof(long long) + tables.phase.values.size() * sizeof(double))
        throw std::runtime_error("glory: the phase table has the wrong size");
    std::memcpy(&tables.phase.mieSeries, cached.bytes.data(), sizeof(long long));
    std::memcpy(tables.phase.values.data(), cached.bytes.data() + sizeof(long long), tables.phase.values.size() * sizeof(double));
    tables.outcome = cached.outcome;
    tables.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return tables;
}

double deckAsymmetry(const Settings& s)
{
    constexpr double kGreenNm = 550.0;
    const double x = 2.0 * physics::kPi * s.effectiveRadiusUm / (kGreenNm * 1e-3);
    return mie::efficiencies(mie::mieCoefficients(x, {optics::waterRefractiveIndex(kGreenNm), 0.0})).asymmetry;
}

const scene::Component& component()
{
    static const Glory instance;
    return instance;
}

} // namespace aurorawall::components::glory
