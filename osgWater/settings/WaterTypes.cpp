// The per-channel water presets. Each channel stands for one wavelength: red 650 nm, green
// 550 nm, blue 450 nm. A natural water is pure water plus three constituents (the usual
// case-2 bio-optical decomposition, e.g. Mobley, "Light and Water", 1994, ch. 3):
//  - pure water: absorption from Pope & Fry, Appl. Opt. 36, 8710 (1997), 0.340 / 0.0565 /
//    0.00922 per metre; scattering of pure fresh water from Morel (1974), 0.0031 per metre at
//    450 nm falling as wavelength^-4.32; half of it scattered backwards (it is symmetric);
//  - coloured dissolved organic matter: a_g(l) = a_g(440) exp(-0.014 (l - 440)), Bricaud, Morel &
//    Prieur, Limnol. Oceanogr. 26, 43 (1981);
//  - particles: absorption a_p(l) = a_p(440) exp(-0.011 (l - 440)) (non-algal particles, Babin et
//    al., J. Geophys. Res. 108 (2003)); scattering b_p(l) = b_p(550) (550 / l); backscattered share
//    0.0183, Petzold's (1972) average particle phase function as tabulated by Mobley (1994).
#include <osgWater/WaterTypes>
#include <osg/Notify>
#include <osgWater/WaterSettings>
#include <cmath>

using namespace osgWater;

namespace {

const float kWavelength[3] = { 650.0f, 550.0f, 450.0f };
const float kPureAbsorption[3] = { 0.340f, 0.0565f, 0.00922f };
const float kParticleBackscatterRatio = 0.0183f;

float pureScattering(float lambda) { return 0.0031f * std::pow(lambda / 450.0f, -4.32f); }

std::vector<WaterType> makeTypes()
{
    // constituents chosen inside the ranges the sources above report for each kind of water;
    // the comment says what the result looks like (clarity: the depth where the green channel's
    // line-of-sight transmittance falls to 10%)
    std::vector<WaterType> t;
    // oligotrophic mountain lake: little CDOM, few particles; ~10 m clarity, blue-green shallows
    t.push_back({ "clear-lake", "clear mountain lake", { 0.05f, 0.01f, 0.15f }, {} });
    // eutrophic pond: humic CDOM, algae and silt; brown-green, ~1 m clarity
    t.push_back({ "murky-pond", "murky pond", { 1.0f, 0.5f, 1.5f }, {} });
    // oligotrophic tropical sea (Jerlov oceanic type I): ~20 m clarity, deep blue
    t.push_back({ "tropical-sea", "tropical sea", { 0.01f, 0.005f, 0.05f }, {} });
    for (WaterType& w : t) w.optics = naturalWater(w.constituents);
    return t;
}

}

WaterOptics osgWater::pureWater() { return naturalWater(WaterConstituents()); }

WaterOptics osgWater::naturalWater(const WaterConstituents& c)
{
    WaterOptics o;
    for (int i = 0; i < 3; ++i) {
        const float l = kWavelength[i];
        const float bw = pureScattering(l);
        const float bp = c.particleScattering550 * 550.0f / l;
        o.absorption[i] = kPureAbsorption[i] + c.cdomAbsorption440 * std::exp(-0.014f * (l - 440.0f))
                        + c.particleAbsorption440 * std::exp(-0.011f * (l - 440.0f));
        o.scattering[i] = bw + bp;
        o.backscattering[i] = 0.5f * bw + kParticleBackscatterRatio * bp;
    }
    return o;
}

const std::vector<WaterType>& osgWater::waterTypes()
{
    static const std::vector<WaterType> types = makeTypes();
    return types;
}

const WaterType* osgWater::findWaterType(const std::string& name)
{
    for (const WaterType& t : waterTypes())
        if (t.name == name) return &t;
    return nullptr;
}

std::string osgWater::waterTypeNames()
{
    std::string names;
    for (const WaterType& t : waterTypes()) names += (names.empty() ? "" : ", ") + t.name;
    return names;
}

void osgWater::applyWaterType(WaterSettings& s, const WaterType& type)
{
    s.setWaterModel(WaterSettings::WATER_PER_CHANNEL);
    s.setAbsorption(type.optics.absorption);
    s.setScattering(type.optics.scattering);
    s.setBackscattering(type.optics.backscattering);
}

bool osgWater::applyWaterType(WaterSettings& s, const std::string& name)
{
    const WaterType* type = findWaterType(name);
    if (!type) {
        OSG_WARN << "osgWater: no water type \"" << name << "\" (there are " << waterTypeNames()
                 << "); the settings are kept" << std::endl;
        return false;
    }
    applyWaterType(s, *type);
    return true;
}
