/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SPECTRUM
#define OSGWATER_SPECTRUM 1

#include <osgWater/Export>

//! The physics of wind waves, in SI units and double precision: what the wave spectrum's FFT
//! cascades realise. The dispersion of gravity-capillary waves over finite depth; the JONSWAP
//! frequency spectrum of a wind of a given speed blowing over a given fetch (Hasselmann et al. 1973),
//! with the TMA depth factor (Kitaigorodskii's form, Bouws et al. 1985); the frequency-dependent
//! cos^2s(theta/2) directional spreading (Mitsuyasu et al. 1975, Hasselmann 1980's exponents) with
//! Horvath's swell term (2015); and the spectrum over wavenumber vectors they make together.
namespace osgWater { namespace spectrum {

const double kGravity = 9.81;                 //!< m/s^2
const double kTensionOverDensity = 0.074e-3;  //!< sigma / rho of water, m^3/s^2
const double kDeep = 1.0e9;                   //!< a depth (m) that is deep water for every wave

//! Angular frequency (rad/s) of a wave of wavenumber k (rad/m) on water `depth` metres deep:
//! omega^2 = (g k + (sigma/rho) k^3) tanh(k h). 0 for k <= 0 or depth <= 0.
OSGWATER_EXPORT double angularFrequency(double k, double depth);
//! d omega / d k (m/s), the group velocity.
OSGWATER_EXPORT double groupVelocity(double k, double depth);
//! The wavenumber (rad/m) whose angular frequency is omega (the dispersion inverted; Newton).
OSGWATER_EXPORT double wavenumber(double omega, double depth);

//! JONSWAP's parameters for a wind of `windSpeed` m/s at 10 m over `fetch` metres:
//! alpha = 0.076 (U^2 / (F g))^0.22, omega_p = 22 (g^2 / (U F))^(1/3), gamma = 3.3.
struct Jonswap { double alpha = 0.0, peakOmega = 0.0, gamma = 3.3; };
OSGWATER_EXPORT Jonswap jonswap(double windSpeed, double fetch);
//! S(omega) (m^2 s): alpha g^2 / omega^5 exp(-5/4 (omega_p/omega)^4) gamma^r,
//! r = exp(-(omega - omega_p)^2 / (2 sigma^2 omega_p^2)), sigma 0.07 below the peak, 0.09 above.
OSGWATER_EXPORT double jonswapSpectrum(double omega, const Jonswap& j);
//! TMA's depth factor at omega on water `depth` deep, with omega_h = omega sqrt(h / g):
//! omega_h^2 / 2 up to 1, 1 - (2 - omega_h)^2 / 2 up to 2, then 1.
OSGWATER_EXPORT double tmaFactor(double omega, double depth);

//! The spreading exponent s at omega: s_p (omega/omega_p)^5 below the peak, s_p (omega/omega_p)^-2.5
//! above, s_p = 11.5 (g / (omega_p U))^2.5; plus Horvath's swell, 16 tanh(omega_p / omega) swell^2.
OSGWATER_EXPORT double spreadExponent(double omega, double peakOmega, double windSpeed, double swell);
//! D(theta) = Q(s) |cos(theta / 2)|^(2s), normalised over a full turn; theta from the wind.
OSGWATER_EXPORT double directionalSpread(double theta, double s);
//! The mean of cos(theta) under D: s / (s + 1).
OSGWATER_EXPORT double meanCosine(double s);

//! Cox and Munk's (1954) mean square slope of the sea under a wind of `windSpeed` m/s (clean
//! surface): 0.003 + 0.00512 U, the slopes of every wave down to the capillaries together, measured
//! from the sun's glitter. 0 without wind (no waves at all).
OSGWATER_EXPORT double coxMunkSlopeVariance(double windSpeed);

//! Everything that sets the spectrum of a surface's wind waves, in physical units.
struct WindSea {
    double windSpeed = 5.0;     //!< m/s at 10 m
    double fetch = 1000.0;      //!< m of water the wind has blown over
    double depth = kDeep;       //!< m (TMA)
    double windDirection = 0.0; //!< radians from +x towards +y: where the wind blows to
    double spread = 0.0;        //!< 0 the wind's directional spreading ... 1 every direction alike
    double swell = 0.0;         //!< 0 .. 1, Horvath's: longer crests, narrower spreading
};
//! The spectrum over wavenumber vectors (m^4): S(omega) TMA(omega) d omega/dk D(theta) / k, so that
//! its integral over the plane is the height variance. 0 at k = 0.
OSGWATER_EXPORT double wavenumberSpectrum(double kx, double ky, const WindSea& sea);

} }

#endif
