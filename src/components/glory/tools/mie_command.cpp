#include "components/glory/tools/mie_command.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "common/decimal_number.h"
#include "physics/constants.h"
#include "components/glory/mie/mie_scattering.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace aurorawall::components::glory::tools {

namespace {

namespace po = boost::program_options;

// Below x = 1e-4 the exact series loses its small terms to cancellation, about 2^-53/x² of the
// scattering efficiency (1e-4 off at x = 1e-6, the asymmetry's sign wrong at 1e-8, NaN below 1e-154;
// tests/components/glory/mie/mie_test.cpp, against the Rayleigh limit): x is held to [1e-4, 1e5].
constexpr double kMinSizeParameter = 1e-4;
constexpr double kMaxSizeParameter = 1e5;
constexpr double kMaxRealPart = 10.0;
constexpr double kMaxAbsorption = 100.0;

std::string number(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

// "0,1,2.5,180" → degrees, each finite in [0, 180].
std::vector<double> parseAngles(const std::string& list, const cli::CommandLine& cli)
{
    std::vector<double> degrees;
    size_t begin = 0;
    for (;;) {
        const size_t end = list.find(',', begin);
        const std::string word = list.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        // An underflow (a subnormal such as 4.9e-324) is an angle in range.
        const std::optional<double> angle = common::finiteDecimal(word);
        const double value = angle.value_or(-1.0);
        if (!(value >= 0.0 && value <= 180.0))
            throw cli.usageError("--angles-deg: '" + common::echoedInput(word) + "' is not an angle in [0, 180] degrees (in '" + common::echoedInput(list) + "')");
        degrees.push_back(value);
        if (end == std::string::npos) return degrees;
        begin = end + 1;
    }
}

// cos θ as sin(90° − θ): exactly 1, 0 and −1 at 0°, 90° and 180°.
double cosineOfDegrees(double degrees) { return std::sin((90.0 - degrees) * physics::kDegree); }

void checkRange(const cli::CommandLine& cli, const char* option, double value, double low, bool lowIncluded,
                double high)
{
    const bool aboveLow = lowIncluded ? value >= low : value > low;
    if (!(aboveLow && value <= high))
        throw cli.usageError(std::string("--") + option + " must be in " + (lowIncluded ? "[" : "(") + number(low) +
                             ", " + number(high) + "] (got " + number(value) + ")");
}

} // namespace

int runMieCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("mie", out, err, [&] {
        cli::CommandLine cli(
            "mie",
            "Usage: aurorawall mie --n N --k K --x X [--angles-deg LIST]\n"
            "Exact Mie scattering by a homogeneous sphere of refractive index m = n - ik (k >= 0 absorbs) and size\n"
            "parameter x = 2 pi r / lambda (Bohren & Huffman 1983; Wiscombe 1980). Prints CSV\n"
            "x,n,k,terms,qext,qsca,qabs,qback,g,s1_0_re,s1_0_im,s1_180_re,s1_180_im and, with --angles-deg, an empty\n"
            "line and angle_deg,i_parallel,i_perpendicular,s1_re,s1_im,s2_re,s2_im (i_parallel = |S2|^2,\n"
            "i_perpendicular = |S1|^2) (docs/GLORY.md). Exit status: 0 success, 1 output not written, 2 usage error.\n");
        double n = 0.0, k = 0.0, x = 0.0;
        std::string angleList;
        cli.add()("n", po::value<double>(&n)->required(), "real part of the refractive index, 1 to 10 (tested 1-3)")(
            "k", po::value<double>(&k)->required(),
            "absorption: minus the imaginary part of m = n - ik, 0 to 100 (tested 0-10)")(
            "x", po::value<double>(&x)->required(), "size parameter 2 pi r / lambda, 1e-4 to 1e5 (tested 1e-4 to 2e4; below 1e-4 the series "
                                               "cancels: use the Rayleigh limit)")(
            "angles-deg", po::value<std::string>(&angleList),
            "scattering angles in degrees, comma-separated, each in [0, 180] (e.g. 0,1,2.5,180)");
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        checkRange(cli, "x", x, kMinSizeParameter, true, kMaxSizeParameter);
        checkRange(cli, "n", n, 1.0, true, kMaxRealPart);
        checkRange(cli, "k", k, 0.0, true, kMaxAbsorption);
        const std::vector<double> angles = cli.given("angles-deg") ? parseAngles(angleList, cli) : std::vector<double>{};

        const mie::MieCoefficients c = mie::mieCoefficients(x, {n, k});
        const mie::Efficiencies q = mie::efficiencies(c);
        const std::complex<double> forward = mie::amplitudesAtCosine(c, 1.0).s1;
        const std::complex<double> backward = mie::amplitudesAtCosine(c, -1.0).s1;
        out << "x,n,k,terms,qext,qsca,qabs,qback,g,s1_0_re,s1_0_im,s1_180_re,s1_180_im\n";
        out << number(x) << ',' << number(n) << ',' << number(k) << ',' << c.a.size() << ',' << number(q.extinction)
            << ',' << number(q.scattering) << ',' << number(q.absorption()) << ',' << number(q.backscatter) << ','
            << number(q.asymmetry) << ',' << number(forward.real()) << ',' << number(forward.imag()) << ','
            << number(backward.real()) << ',' << number(backward.imag()) << '\n';
        if (angles.empty()) return;
        out << "\nangle_deg,i_parallel,i_perpendicular,s1_re,s1_im,s2_re,s2_im\n";
        for (double degrees : angles) {
            const mie::Amplitudes s = mie::amplitudesAtCosine(c, cosineOfDegrees(degrees));
            out << number(degrees) << ',' << number(std::norm(s.s2)) << ',' << number(std::norm(s.s1)) << ','
                << number(s.s1.real()) << ',' << number(s.s1.imag()) << ',' << number(s.s2.real()) << ','
                << number(s.s2.imag()) << '\n';
        }
    });
}

} // namespace aurorawall::components::glory::tools
