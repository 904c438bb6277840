/* Full numerical Greenwood-Williamson solution for two rough elastic spheres
   (Feng et al. 2016, Sections 2-6; Greenwood & Tripp 1967): the expected
   pressure p(r) (Feng Eq. 17) and the bulk deformation w(r) (Eq. 20) solved
   together by Newton-Raphson (Eqs. 46-53) at the m Gauss-Legendre points of
   [0, abar], with the influence coefficients alpha_ij (Eqs. 48, 56)
   precomputed per m and the singular diagonal set by Eq. 58.

   Non-dimensional sigma-form (Feng Eqs. 27-29, Table 1), derived here:
     r = sqrt(2 R sigma) r*, w = sigma w*, p = E sqrt(sigma/(8R)) p*,
     p*(r*) = mu F_3/2(w*(r*) + r*^2 - alpha'),       alpha' = delta/sigma
     w*(r*) = (2/pi) int_0^abar* t* / (r* + t*) p*(t*) K(k) dt*,
              k = 2 sqrt(r* t*)/(r* + t*)   (K of modulus k)
     P* = P/P_h(sigma) = (3 sqrt 2/8) int 2 pi r* p* dr*,
   and P/P_h(delta) = P* alpha'^-3/2 (the delta-form value, Table 3).

   Seed errors found (Feng, OCR text), each checked by dimensions and by
   the Hertz identities:
   - Eq. 23: N beta^1/2 = 3 mu/(8 sigma sqrt(2R)), not 3 mu/(8 sqrt(2 R sigma))
     (N beta^1/2 has dimension m^-3/2; mu is dimensionless by Eq. 22).
   - Eq. 24: hence C = mu E/(sigma sqrt(8R)), not mu E/sqrt(8 R sigma); only
     with this does p = C sigma^3/2 F_3/2 scale as E sqrt(sigma/(8R)) (Table 1).
   - Eqs. 28, 31: the kernel is t* / (t* + r*), not t* / (t* + r*^2) (Eq. 20
     non-dimensionalised; the printed form is not dimensionless-consistent).
   - Eq. 41: the integrand is Delta p(t), not Delta p(r).
   - Eq. 60: min{alpha, |alpha'|} is read as min{|alpha|, |alpha'|} (for
     alpha' < 0 the printed form shrinks the domain below 1.75 a).
   - Eq. 30 (delta-form) holds when phi there is the N(1, alpha^2) density;
     this code uses the sigma-form for all alpha'.

   Two departures from the paper, both optional:
   - the Jacobian is analytic, J_ij = delta_ij + (3/2) mu F_1/2(h_i) A_ij,
     instead of the finite differences of Eq. 55 (same quadratic
     convergence, no perturbation parameter);
   - F_3/2 is evaluated exactly (dc_gw_F) by default; DC_GW_F32_GAUSS10
     reproduces the paper's choice (Sec. 6.2: 10 Gauss points on [d, 5 sigma]).
   Force integral (Eq. 21): DC_GW_FORCE_DOMAIN integrates over [0, abar] with
   the same points (Eq. 54); DC_GW_FORCE_FULL adds the pressure beyond abar
   (w there from the same influence integral, 48 Gauss points out to where
   r*^2 - alpha' = 14), the paper's Sec. 5.2.1 reading of Eq. 21.

   Feng Table 3 was not computed with the printed Eq. 60. All 18 printed
   values (m = 5 ... 200, alpha = 0.1, 1, 5) are reproduced within 6e-6 by
   abar = (1.5 + alpha) (R delta)^1/2, the force by Eq. 54 alone (FORCE_DOMAIN)
   and F_3/2 by GAUSS10; found by scanning abar for each alpha (the m = 5
   and m = 10 values pin it to 0.1%: 3.578, 1.768, 2.055 in r* units, i.e.
   1.600, 2.500, 6.500 (R delta)^1/2). At alpha = 1 that domain is too small:
   Eq. 54 leaves out the 0.153% of the force beyond abar, and the pressure
   inside comes out 0.041% high (w misses the outer load), so the paper's
   alpha = 1 column lies 0.112% below the domain-converged value; at
   alpha = 0.1 and 5 both effects are below 1e-6 (test_gw_solver.c).
   This is the reference, not the hot path: it allocates. */
#ifndef DC_GW_SOLVER_H
#define DC_GW_SOLVER_H

#ifdef __cplusplus
extern "C" {
#endif

enum { DC_GW_FORCE_DOMAIN = 0, DC_GW_FORCE_FULL = 1 };
enum { DC_GW_F32_EXACT = 0, DC_GW_F32_GAUSS10 = 1 };

#define DC_GW_SOLVER_MAX_HIST 64

/* Influence data for m points on the unit interval (independent of abar). */
typedef struct {
  int m;
  double *x, *s;     /* Gauss-Legendre abscissae, weights on [0, 1] */
  double *alpha;     /* m x m, row-major: alpha_ij (Eq. 56), diagonal by Eq. 58 */
} dc_gw_solver;

typedef struct {
  double domain_scale;  /* abar = domain_scale x Eq. 60 (1 = as printed) */
  double abar;          /* > 0: the domain radius in r* units instead */
  int force_mode;       /* DC_GW_FORCE_* */
  int f32_mode;         /* DC_GW_F32_* */
  double tol;           /* stop when ||dp||/||p|| < tol (Eq. 59) */
  int max_iter;
} dc_gw_solve_opts;

typedef struct {
  double Pstar_sigma;   /* P/P_h(sigma) */
  double Pstar_delta;   /* P/P_h(delta) (alpha' > 0 only, else 0) */
  double abar;          /* domain radius, r* units */
  double p0;            /* p*(r_1), the pressure at the innermost point */
  int iterations;
  double hist[DC_GW_SOLVER_MAX_HIST];  /* ||dp||/||p|| per iteration (Eq. 59) */
} dc_gw_solve_result;

/* Default options: domain_scale 1, abar 0, FORCE_FULL, F32_EXACT, tol 1e-12, 50
   (the rounding floor of ||dp||/||p|| is ~1e-14 at m = 100). */
dc_gw_solve_opts dc_gw_solve_default_opts(void);

/* Gauss points and alpha_ij for m in [2, 1000]. DC_EDOM outside;
   DC_ERANGE if the tables cannot be allocated (*S untouched on either). */
int dc_gw_solver_init(dc_gw_solver *S, int m);
void dc_gw_solver_free(dc_gw_solver *S);

/* Solve for alpha' = delta/sigma in [-10, 1e4], mu in (0, 1e3]; options:
   domain_scale > 0 with the resulting domain radius below 1e3 (as for
   abar, in [0, 1e3)), force_mode and f32_mode one of their enums, tol
   finite, max_iter > 0. DC_EDOM outside. DC_ENOCONV if the tolerance was
   not met (result holds the last iterate). DC_ERANGE, result untouched,
   if the Jacobian is singular, the iteration leaves the range of doubles,
   or P/P_h(delta) overflows (alpha' > 0 below ~1e-205). */
int dc_gw_solve(const dc_gw_solver *S, double alpha_p, double mu,
                const dc_gw_solve_opts *o, dc_gw_solve_result *r);

#ifdef __cplusplus
}
#endif
#endif
