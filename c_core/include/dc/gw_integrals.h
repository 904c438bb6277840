/* Greenwood-Williamson height integrals

     F_n(h) = int_h^inf (s - h)^n phi(s) ds,   phi(s) = exp(-s^2/2)/sqrt(2 pi),

   for n = 0, 1/2, 1, 3/2 (Greenwood & Williamson 1966; review Eqs. 31-32,
   35-36, 82-84; Feng et al. 2016 Eq. 17). h = d/sigma is the separation of
   the mean planes in units of the rms summit height; h < 0 means the
   surfaces are pressed past the mean plane. Identities (exact, used by the
   tests): F_n' = -n F_{n-1};  F_{n+1} = n F_{n-1} - h F_n.

   Closed forms, checked against mpmath quadrature to 1e-37 by
   tests/reference/gen_gw_integrals.py (z = h^2/4):
     F_0   = erfc(h/sqrt 2)/2
     F_1   = phi(h) - h F_0
     h > 0:
     F_1/2 = h^3/2 e^{-h^2/4} [K_3/4(z) - K_1/4(z)] / (4 sqrt pi)
     F_3/2 = h^1/2 e^{-h^2/4} [(h^2+1) K_1/4(z) - h^2 K_3/4(z)] / (4 sqrt pi)
     h < 0, x = -h (the K forms need sqrt h and do not apply):
     F_-1/2 = sqrt(pi/8) x^1/2 e^{-z} [I_-1/4 + I_1/4](z)
     F_1/2  = sqrt(2 pi)/8 x^3/2 e^{-z} [I_-1/4 + I_1/4 + I_-3/4 + I_3/4](z)
     F_3/2  = F_-1/2 / 2 + x F_1/2
     h = 0: F_n(0) = 2^{n/2} Gamma((n+1)/2) / (2 sqrt pi).
   All follow from F_n(h) = Gamma(n+1) phi(h) e^{h^2/4} U(n+1/2, h) with U the
   parabolic cylinder function (DLMF 12.5.1, 12.7.10-11).

   Seed errors found (review, OCR text):
   - Eq. 36 reads beta* = beta (exp(-h^2/4)/sqrt(2 pi) - h erf(h/sqrt 2)/2).
     Correct: beta* = beta F_1(h) = beta (exp(-h^2/2)/sqrt(2 pi)
     - h erfc(h/sqrt 2)/2): exp(-h^2/2), not /4, and erfc, not erf (the
     printed form is negative for h > 1 and does not tend to |h| as
     h -> -inf). Checked against quadrature.
   - Eq. 35 (F_3/2, Bessel K form) is right as printed, for h > 0 only.
   - Eq. 84 (Hisakado chi*, an I-Bessel form of F_1/2) must read
     sqrt(pi)/(4 sqrt(2h)), not sqrt(pi)/(4 sqrt(2) h) as Table 5 prints it;
     with I_5/4 = I_-3/4 - I_1/4/(2z) and I_-nu - I_nu = (sqrt 2/pi) K_nu
     (nu = 1/4, 3/4) it then reduces to the F_1/2 K form above. Checked by
     the large-h limit F_1/2 -> phi(h) Gamma(3/2) h^-3/2 and by quadrature.
   - Eqs. 30, 32 print the lower limits -1 and 1; both are d (resp. h).

   Two evaluation paths:
   - dc_gw_F / dc_gw_F_all (hot path): piecewise Chebyshev series of degree
     <= 17 on unit intervals, of F_n itself for -10 <= h < 0 and of
     G_n = F_n/phi for 0 <= h < 20, coefficients generated in 40-digit
     arithmetic (gw_integrals_cheb.h); for h < -10 the asymptotic series
     F_n = sum_j C(n,2j) (2j-1)!! |h|^{n-2j} (omitted tail ~ phi(h) < 1e-22);
     for h >= 20 the asymptotic series G_n = sum_k (-1/2)^k/k!
     Gamma(n+2k+1) h^-(n+2k+1). Relative error ~1e-16 (tested < 8e-16 over
     the committed table), no allocation, no GSL. The Clenshaw recurrences
     run on the processor's FMA instructions where it has them (GCC, x86-64:
     a clone chosen at load time; the same bits as the library's fma), the
     four orders of dc_gw_F_all side by side: ~40 ns per call, ~330 before.
   - dc_gw_F_closed: the Bessel closed forms above via GSL's fractional-
     order K_nu and I_nu (GSL is used because C has no fractional-order
     Bessel functions). Slower, and F_1 and F_3/2 lose ~2 log10(h) digits for
     large h by cancellation (the bracket is O(1/h^2)); kept as the
     independent second evaluation and for the benchmark.
   Domain: h finite and h >= -1e100 (else DC_EDOM). For h > ~38.6 the result
   is below the smallest normal double: it is returned gradually
   underflowed (subnormal, then 0), with DC_OK. */
#ifndef DC_GW_INTEGRALS_H
#define DC_GW_INTEGRALS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Orders, as indices: n = order/2. */
enum { DC_GW_F0 = 0, DC_GW_F12 = 1, DC_GW_F1 = 2, DC_GW_F32 = 3 };

/* Lower end of the domain of h. */
#define DC_GW_H_MIN (-1e100)

/* F_n(h), n = order/2 with order in {0,1,2,3}: fast path (see above). */
int dc_gw_F(int order, double h, double *F);

/* All four F_0, F_1/2, F_1, F_3/2 at once (shares the exp); F[order]. */
int dc_gw_F_all(double h, double F[4]);

/* F_3/2 and F_1/2 at once, for the GW closed form's force and stiffness
   (dc_gw_bound_force, dc/gw_rough.h): on DC_GW_F32P_LO <= h <
   DC_GW_F32P_HI from polynomials of degree 9 on pieces of width 1/8
   (c_core/src/gw_F32_poly.h, tests/reference/gen_gw_F32_poly.py, from
   mpmath): relative error 1.2e-16 in the coefficients, below 3e-16 as
   evaluated (tests/unit/test_gw_integrals.c, against the committed mpmath
   table and dc_gw_F_all), about a quarter of dc_gw_F_all's instructions;
   elsewhere dc_gw_F_all. Domain and status as dc_gw_F_all. */
#define DC_GW_F32P_LO (-10.0)
#define DC_GW_F32P_HI 3.0
int dc_gw_F32_F12(double h, double *F32, double *F12);
/* F_n(h) from the closed forms (erfc; GSL Bessel K_nu, I_nu), same domain.
   For |h| < 1e-20 the h = 0 values (exact to rounding: the Bessel forms
   fail where h^2/4 underflows); DC_ERANGE, output untouched, if GSL
   reports an error (none seen over the domain). */
int dc_gw_F_closed(int order, double h, double *F);

#ifdef __cplusplus
}
#endif
#endif
