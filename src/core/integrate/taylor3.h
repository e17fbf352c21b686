// The third-order Taylor step (TY3) of doc/model.md §2, shared by fix nve/sphere/ty3, its
// KOKKOS variant and the unit tests: per component, per grain, and as per-grain kernels
// over a grain accessor G (grains/host_grains.h). The jerk is the backward
// difference ȧ ≈ (a − a_prev)/Δt, so ȧΔt = a − a_prev appears below.
#ifndef PW_INTEGRATE_TAYLOR3_H
#define PW_INTEGRATE_TAYLOR3_H

#include "pw_inline.h"

namespace porewater {

// a = f/m and α = T/I of a solid sphere (I = 2/5 m r²); ftm2v converts force/mass to the
// unit style's acceleration
PW_INLINE void sphere_accelerations(const double ftm2v, const double mass, const double radius,
                                    const double *f, const double *torque, double *a,
                                    double *alpha)
{
  const double to_a = ftm2v / mass;
  const double to_alpha = to_a / (0.4 * radius * radius);
  for (int k = 0; k < 3; k++) {
    a[k] = to_a * f[k];
    alpha[k] = to_alpha * torque[k];
  }
}

// x ← x + vΔt + ½aΔt² + ⅙ȧΔt³
PW_INLINE double ty3_displacement(const double v, const double a, const double a_prev,
                                  const double dt)
{
  return dt * (v + dt * (0.5 * a + (a - a_prev) / 6.0));
}

// v ← v + aΔt + ½ȧΔt² (also ω with α = T/I). Alone this is two-step Adams–Bashforth:
// local error (5/12)ä Δt³, so velocities and positions are second order globally.
PW_INLINE double ty3_velocity_change(const double a, const double a_prev, const double dt)
{
  return dt * (a + 0.5 * (a - a_prev));
}

// Optional correction once a_new = a(t+Δt) is known, turning the velocity step into
// three-step Adams–Moulton v_new = v + Δt(5/12 a_new + 2/3 a − 1/12 a_prev): third order.
// a_step = a − a_prev is the jerk increment the predictor used.
PW_INLINE double ty3_velocity_correction(const double a_new, const double a, const double a_step,
                                         const double dt)
{
  return (5.0 / 12.0) * dt * (a_new - a - a_step);
}

// The same on a start-up step (no a_prev, ȧ taken as 0): the trapezoid rule,
// v_new = v + ½Δt(a + a_new), whose one-off O(Δt³) error keeps the scheme third order.
PW_INLINE double ty3_startup_velocity_correction(const double a_new, const double a,
                                                 const double dt)
{
  return 0.5 * dt * (a_new - a);
}

// ---------------------------------------------------------------------------------------
// One grain's step as fix nve/sphere/ty3 takes it, with a = f/m and α = T/I, and its
// per-grain history row h (columns below).

enum Ty3Column {
  TY3_A_PREV = 0,         // a of the previous step (3)
  TY3_ALPHA_PREV = 3,     // α of the previous step (3)
  TY3_STATE = 6,          // Ty3State
  TY3_A_STEP = 7,         // a − a_prev this step's predictor used (3), corrector only
  TY3_ALPHA_STEP = 10,    // α − α_prev (3), corrector only
  TY3_COLUMNS = 7,        // without the corrector
  TY3_COLUMNS_CORRECTOR = 13
};
// TY3_STARTUP: the last predictor step was a start-up step (no a_prev: jerk taken as 0)
enum Ty3State { TY3_NO_HISTORY = 0, TY3_STARTUP = 1, TY3_RUNNING = 2 };

// Before the forces: x, v, ω to t+Δt from a(t) and the history. Without history (a new
// grain, a new step size) the jerk is taken as zero.
PW_INLINE void ty3_predict_grain(double *x, double *v, double *omega, const double *a,
                                 const double *alpha, const double dt, const int corrector,
                                 double *h)
{
  const bool startup = h[TY3_STATE] == TY3_NO_HISTORY;
  for (int k = 0; k < 3; k++) {
    const double a_prev = startup ? a[k] : h[TY3_A_PREV + k];
    const double alpha_prev = startup ? alpha[k] : h[TY3_ALPHA_PREV + k];
    x[k] += ty3_displacement(v[k], a[k], a_prev, dt);
    v[k] += ty3_velocity_change(a[k], a_prev, dt);
    omega[k] += ty3_velocity_change(alpha[k], alpha_prev, dt);
    if (corrector) {
      h[TY3_A_STEP + k] = a[k] - a_prev;
      h[TY3_ALPHA_STEP + k] = alpha[k] - alpha_prev;
    }
    h[TY3_A_PREV + k] = a[k];
    h[TY3_ALPHA_PREV + k] = alpha[k];
  }
  h[TY3_STATE] = startup ? TY3_STARTUP : TY3_RUNNING;
}

// After the forces, with the corrector: v and ω corrected with a(t+Δt) = a_new.
PW_INLINE void ty3_correct_grain(double *v, double *omega, const double *a_new,
                                 const double *alpha_new, const double dt, const double *h)
{
  const bool startup = h[TY3_STATE] == TY3_STARTUP;    // this step's predictor started up
  for (int k = 0; k < 3; k++) {
    if (startup) {
      v[k] += ty3_startup_velocity_correction(a_new[k], h[TY3_A_PREV + k], dt);
      omega[k] += ty3_startup_velocity_correction(alpha_new[k], h[TY3_ALPHA_PREV + k], dt);
    } else {
      v[k] += ty3_velocity_correction(a_new[k], h[TY3_A_PREV + k], h[TY3_A_STEP + k], dt);
      omega[k] +=
          ty3_velocity_correction(alpha_new[k], h[TY3_ALPHA_PREV + k], h[TY3_ALPHA_STEP + k], dt);
    }
  }
}

// ---------------------------------------------------------------------------------------
// The two hooks of fix nve/sphere/ty3 as per-grain kernels; history(i) is grain i's row.

template <class G> PW_INLINE void grain_accelerations(const G &g, const int i, const double ftm2v,
                                                     double *a, double *alpha)
{
  const double f[3] = {g.f(i, 0), g.f(i, 1), g.f(i, 2)};
  const double torque[3] = {g.torque(i, 0), g.torque(i, 1), g.torque(i, 2)};
  sphere_accelerations(ftm2v, g.rmass(i), g.radius(i), f, torque, a, alpha);
}

// before the forces: x, v, ω to t+Δt
template <class G, class History> struct Ty3Predict {
  G g;
  History history;
  int groupbit, corrector;
  double dt, ftm2v;
  PW_INLINE void operator()(const int i) const
  {
    if (!(g.mask(i) & groupbit)) return;
    double a[3], alpha[3], x[3], v[3], omega[3];
    grain_accelerations(g, i, ftm2v, a, alpha);
    for (int k = 0; k < 3; k++) {
      x[k] = g.x(i, k);
      v[k] = g.v(i, k);
      omega[k] = g.omega(i, k);
    }
    ty3_predict_grain(x, v, omega, a, alpha, dt, corrector, history(i));
    for (int k = 0; k < 3; k++) {
      g.x(i, k) = x[k];
      g.v(i, k) = v[k];
      g.omega(i, k) = omega[k];
    }
  }
};

// after the forces, with the corrector: v and ω corrected with a(t+Δt)
template <class G, class History> struct Ty3Correct {
  G g;
  History history;
  int groupbit;
  double dt, ftm2v;
  PW_INLINE void operator()(const int i) const
  {
    if (!(g.mask(i) & groupbit)) return;
    double a[3], alpha[3], v[3], omega[3];
    grain_accelerations(g, i, ftm2v, a, alpha);
    for (int k = 0; k < 3; k++) {
      v[k] = g.v(i, k);
      omega[k] = g.omega(i, k);
    }
    ty3_correct_grain(v, omega, a, alpha, dt, history(i));
    for (int k = 0; k < 3; k++) {
      g.v(i, k) = v[k];
      g.omega(i, k) = omega[k];
    }
  }
};

}    // namespace porewater

#endif
