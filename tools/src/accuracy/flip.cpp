// LDR-FLIP (Andersson et al. 2020). Equation and section numbers are the paper's; the constants
// are its Table/section values, and the colour transforms those of its reference implementation
// (sRGB primaries, D65 white).
#include "kiln/tools/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace kiln::tools {
namespace {

using Vec3 = std::array<double, 3>;
using Plane = std::vector<float>;
constexpr double kPi = 3.14159265358979323846;

// Section 4.1-4.3: exponents and the error redistribution.
constexpr double kQc = 0.7;              // compresses the colour difference
constexpr double kPc = 0.4;              // where the redistribution's knee is (fraction of cmax)
constexpr double kPt = 0.95;             // the error assigned at the knee
constexpr double kQf = 0.5;              // compresses the feature difference
constexpr double kFeatureWidth = 0.082;  // degrees: the edge and point detectors' width (4.2)

// Linear sRGB to CIE XYZ (D65), and back.
constexpr double kRgbToXyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};
constexpr double kXyzToRgb[3][3] = {{3.241003232976358, -1.537398969488785, -0.498615881996363},
                                    {-0.969224252202516, 1.875929983695176, 0.041554226340085},
                                    {0.055639419851975, -0.204011206123910, 1.057148977187533}};

Vec3 Mul(const double m[3][3], const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

const Vec3& White() {  // the XYZ of linear RGB (1, 1, 1): the reference illuminant
    static const Vec3 w = Mul(kRgbToXyz, {1.0, 1.0, 1.0});
    return w;
}

double SrgbDecode(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// YCxCz, the linearised CIELAB the contrast sensitivity functions are defined in (section 4.1).
Vec3 XyzToYCxCz(const Vec3& xyz) {
    const Vec3& w = White();
    const double y = xyz[1] / w[1];
    return {116.0 * y - 16.0, 500.0 * (xyz[0] / w[0] - y), 200.0 * (y - xyz[2] / w[2])};
}
Vec3 YCxCzToXyz(const Vec3& o) {
    const Vec3& w = White();
    const double y = (o[0] + 16.0) / 116.0;
    return {(o[1] / 500.0 + y) * w[0], y * w[1], (y - o[2] / 200.0) * w[2]};
}

Vec3 XyzToLab(const Vec3& xyz) {
    const Vec3& w = White();
    constexpr double d = 6.0 / 29.0;
    auto f = [&](double t) {
        return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / w[0]), fy = f(xyz[1] / w[1]), fz = f(xyz[2] / w[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Hunt effect (section 4.1): chroma scales with lightness, a' = 0.01 L a, b' = 0.01 L b.
Vec3 Hunt(const Vec3& lab) {
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

// HyAB distance (Abasi et al. 2020): |dL| + ||(da, db)||.
double HyAB(const Vec3& a, const Vec3& b) {
    return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// `in` convolved with kernel kx along x and then ky along y, edges clamped.
Plane Convolve(const Plane& in,
               uint32_t w,
               uint32_t h,
               const std::vector<double>& kx,
               const std::vector<double>& ky) {
    const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
    Plane tmp(in.size()), out(in.size());
    for (uint32_t y = 0; y < h; ++y) {
        for (int x = 0; x < int(w); ++x) {
            double s = 0;
            for (int k = -rx; k <= rx; ++k) {
                s += kx[size_t(k + rx)] *
                     in[size_t(y) * w + size_t(std::clamp(x + k, 0, int(w) - 1))];
            }
            tmp[size_t(y) * w + size_t(x)] = float(s);
        }
    }
    for (int y = 0; y < int(h); ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            double s = 0;
            for (int k = -ry; k <= ry; ++k) {
                s += ky[size_t(k + ry)] * tmp[size_t(std::clamp(y + k, 0, int(h) - 1)) * w + x];
            }
            out[size_t(y) * w + x] = float(s);
        }
    }
    return out;
}

// The contrast sensitivity function of one channel as a sum of Gaussians in the spatial domain
// (eq. 2): S(x) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i), x in degrees, normalised to sum 1.
struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kCsfA{1.0, 0.0047, 0.0, 1e-5};    // achromatic
constexpr Csf kCsfRG{1.0, 0.0053, 0.0, 1e-5};   // red-green
constexpr Csf kCsfBY{34.1, 0.04, 13.5, 0.025};  // blue-yellow
constexpr double kCsfWidest = 0.04;             // the largest b: sets the kernel radius

Plane FilterCsf(const Plane& in, uint32_t w, uint32_t h, const Csf& csf, double ppd) {
    const int r = int(std::ceil(3.0 * std::sqrt(kCsfWidest / (2.0 * kPi * kPi)) * ppd));
    Plane out(in.size(), 0.0f);
    double total = 0;
    std::vector<std::pair<double, std::vector<double>>> terms;
    for (const auto& [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
        if (a == 0) {
            continue;
        }
        std::vector<double> k(size_t(2 * r + 1));
        double sum = 0;
        for (int x = -r; x <= r; ++x) {
            const double deg = double(x) / ppd;
            k[size_t(x + r)] = std::exp(-kPi * kPi * deg * deg / b);
            sum += k[size_t(x + r)];
        }
        const double weight = a * std::sqrt(kPi / b);  // the 2-D kernel is weight * k(x) k(y)
        total += weight * sum * sum;
        terms.emplace_back(weight, std::move(k));
    }
    for (const auto& [weight, k] : terms) {
        const Plane part = Convolve(in, w, h, k, k);
        for (size_t i = 0; i < out.size(); ++i) {
            out[i] += float(weight * part[i] / total);
        }
    }
    return out;
}

// Edge (first derivative) or point (second derivative) detector of a Gaussian of standard
// deviation 0.5 * 0.082 degrees (section 4.2), its positive weights summing to 1 and its negative
// weights to -1; returns the gradient magnitude of the detector along x and y.
Plane Features(const Plane& y, uint32_t w, uint32_t h, double ppd, bool points) {
    const double sd = 0.5 * kFeatureWidth * ppd;
    const int r = int(std::ceil(3.0 * sd));
    std::vector<double> g(size_t(2 * r + 1)), d(g.size());
    double gsum = 0, pos = 0, neg = 0;
    for (int x = -r; x <= r; ++x) {
        const double gx = std::exp(-double(x * x) / (2.0 * sd * sd));
        const double dx = points ? (double(x * x) / (sd * sd) - 1.0) * gx : -double(x) * gx;
        g[size_t(x + r)] = gx;
        d[size_t(x + r)] = dx;
        gsum += gx;
        (dx > 0 ? pos : neg) += dx;
    }
    for (double& v : d) {  // the 2-D kernel d(x) g(y): its positive part sums to pos * gsum
        v = v > 0 ? v / (pos * gsum) : v / (-neg * gsum);
    }
    const Plane fx = Convolve(y, w, h, d, g), fy = Convolve(y, w, h, g, d);
    Plane out(y.size());
    for (size_t i = 0; i < out.size(); ++i) {
        out[i] = std::hypot(fx[i], fy[i]);
    }
    return out;
}

// One image's planes: the contrast-filtered Hunt-adjusted CIELAB (colour pipeline) and the
// normalised achromatic channel's edges and points (feature pipeline).
struct Prepared {
    std::vector<Vec3> lab;
    Plane edges, points;
};

Prepared Prepare(uint32_t w, uint32_t h, const std::vector<float>& rgba, double ppd) {
    const size_t n = size_t(w) * h;
    std::array<Plane, 3> opp{Plane(n), Plane(n), Plane(n)};
    for (size_t i = 0; i < n; ++i) {
        const Vec3 lin{SrgbDecode(std::clamp(double(rgba[i * 4]), 0.0, 1.0)),
                       SrgbDecode(std::clamp(double(rgba[i * 4 + 1]), 0.0, 1.0)),
                       SrgbDecode(std::clamp(double(rgba[i * 4 + 2]), 0.0, 1.0))};
        const Vec3 o = XyzToYCxCz(Mul(kRgbToXyz, lin));
        for (size_t c = 0; c < 3; ++c) {
            opp[c][i] = float(o[c]);
        }
    }
    const Plane fa = FilterCsf(opp[0], w, h, kCsfA, ppd);
    const Plane frg = FilterCsf(opp[1], w, h, kCsfRG, ppd);
    const Plane fby = FilterCsf(opp[2], w, h, kCsfBY, ppd);
    Prepared p;
    p.lab.resize(n);
    Plane y(n);
    for (size_t i = 0; i < n; ++i) {
        Vec3 lin = Mul(kXyzToRgb, YCxCzToXyz({fa[i], frg[i], fby[i]}));
        for (double& c : lin) {
            c = std::clamp(c, 0.0, 1.0);
        }
        p.lab[i] = Hunt(XyzToLab(Mul(kRgbToXyz, lin)));
        y[i] = (opp[0][i] + 16.0f) / 116.0f;  // luminance relative to white, in [0, 1]
    }
    p.edges = Features(y, w, h, ppd, false);
    p.points = Features(y, w, h, ppd, true);
    return p;
}

}  // namespace

Result<FlipMap> Flip(uint32_t width,
                     uint32_t height,
                     const std::vector<float>& reference,
                     const std::vector<float>& test,
                     const FlipOptions& options) {
    const size_t n = size_t(width) * height;
    if (n == 0 || reference.size() != n * 4 || test.size() != n * 4) {
        return Error{DiagCode::kBadCommandLine, "FLIP needs two RGBA images of " +
                                                    std::to_string(width) + "x" +
                                                    std::to_string(height) + " pixels"};
    }
    if (!(options.pixels_per_degree > 0 && options.pixels_per_degree < 1e4)) {
        return Error{DiagCode::kBadCommandLine, "FLIP's pixels per degree must be in (0, 1e4)"};
    }
    const double ppd = options.pixels_per_degree;
    const Prepared r = Prepare(width, height, reference, ppd);
    const Prepared t = Prepare(width, height, test, ppd);
    // The largest colour difference: between Hunt-adjusted green and blue (section 4.1).
    const Vec3 green = Hunt(XyzToLab(Mul(kRgbToXyz, {0.0, 1.0, 0.0})));
    const Vec3 blue = Hunt(XyzToLab(Mul(kRgbToXyz, {0.0, 0.0, 1.0})));
    const double cmax = std::pow(HyAB(green, blue), kQc);
    const double knee = kPc * cmax;
    FlipMap out;
    out.width = width;
    out.height = height;
    out.error.resize(n);
    double sum = 0;
    for (size_t i = 0; i < n; ++i) {
        // Colour error (eq. 5): the compressed HyAB distance mapped to [0, 1], the first pc of
        // the range onto [0, pt] and the rest onto [pt, 1].
        const double e = std::pow(HyAB(r.lab[i], t.lab[i]), kQc);
        const double ec =
            e < knee ? (kPt / knee) * e : kPt + (e - knee) / (cmax - knee) * (1 - kPt);
        // Feature error (eq. 7): the larger difference of edge or point magnitude.
        const double df = std::max(std::abs(double(r.edges[i]) - t.edges[i]),
                                   std::abs(double(r.points[i]) - t.points[i]));
        const double ef = std::pow(std::min(df / std::sqrt(2.0), 1.0), kQf);
        // FLIP (eq. 8): features raise the colour error towards 1.
        const double flip = std::clamp(std::pow(std::min(ec, 1.0), 1.0 - ef), 0.0, 1.0);
        out.error[i] = float(flip);
        sum += flip;
    }
    out.mean = sum / double(n);
    return out;
}

}  // namespace kiln::tools
