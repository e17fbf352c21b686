// Host-free Darcy pore-pressure solver on a cell-centred grid (doc/model.md §3):
//   dp/dt = 1/(beta phi mu) div(k grad p) - 1/(beta phi (1-phi)) (dphi/dt + vbar . grad phi)
// Crank-Nicolson for the diffusion, grain forcing explicit, each row scaled by
// beta phi mu so the system is SPD; Jacobi-preconditioned CG to a stated tolerance.
//
// Use per fluid step (DarcyFluid does this, with the sum over ranks in between):
//   clear_deposits(); deposit every grain at x (or fill solid_volume()/solid_momentum()
//   yourself); update_porosity();
//   fill solid_volume() with the deposits at x + v*interval; update_dphi_dt(interval);
//   StepResult r = step(interval, p_top(t+interval), z_top);  then pressure_gradient().
#ifndef PW_DARCY_SOLVER_H
#define PW_DARCY_SOLVER_H

#include "darcy/grid.h"

#include <vector>

namespace porewater {

struct DarcyParams {
  enum class Bottom { NoFlow, Dirichlet };
  enum class Top { Dirichlet, NoFlow };  // NoFlow: closed box (tests, mass balance)

  double viscosity = 1.0;        // mu_f
  double compressibility = 1.0;  // beta_f
  double kc = 1.0;               // Kozeny-Carman prefactor
  double kmax = 0.0;             // permeability cap, <= 0: none
  double porosity_min = 0.1;     // clamp, as in sphere
  double porosity_max = 0.9;     // must be < 1 (k and the forcing diverge at phi = 1)
  double tol_abs = 0.0;          // stop when max|r_i/A_ii| <= tol_abs + tol_rel*max|p|
  double tol_rel = 1e-10;
  int maxiter = 1000;
  // Converged: CG to the tolerance above. Relaxed: the original program's iteration
  // (sphere): damped fixed-point sweeps toward the Crank-Nicolson value with relaxation
  // theta, stopped when max |change|/|p| <= relaxed_tol at sweep 0, 10, 20, ...
  enum class Scheme { Converged, Relaxed };
  Scheme scheme = Scheme::Converged;
  double theta = 0.05;
  double relaxed_tol = 1e-3;
  Bottom bottom = Bottom::NoFlow;
  double p_bottom = 0.0;  // Dirichlet value at the bottom face
  Top top = Top::Dirichlet;
};

struct StepResult {
  bool converged;
  int iterations;   // CG iterations, or relaxed sweeps
  double residual;  // final max_i |r_i / A_ii|, pressure units (NaN if any is); relaxed:
                    // the largest relative change of the last tested sweep
  double tolerance; // what it had to reach
  int worst_cell;   // flat index of that largest (or first non-finite) |r_i / A_ii|, -1 if none
};

// Fluid volume balance of the discrete equations, summed over the steps since the solver
// was made (kept in the restart state). Each step, multiplying row c by V_cell dt/mu gives
//   beta phi_c dp_c V = dt (inflow through c's Dirichlet faces) + dt (grain source of c)
// exactly (interior face fluxes cancel in pairs), up to the linear solve's residual.
// Volume units: beta p V is the volume the fluid gained by compression.
struct FluidBalance {
  double stored = 0.0;     // sum of beta phi dp V_cell over the active cells of each step
  double boundary = 0.0;   // dt (k_f/mu) (mean p_face - mean p_c)/(dz/2) A over Dirichlet faces
  double grains = 0.0;     // -dt sum (dphi/dt + vbar.grad phi)/(1-phi) V_cell
  double allowance = 0.0;  // what the solve tolerance lets |residual| reach: sum over steps
                           // of tolerance * V dt/mu sum_c A_cc (row c's |r_c| <= A_cc tol)
  double residual() const { return stored - boundary - grains; }
};

class DarcySolver {
 public:
  DarcySolver(const GridGeom &geom, const DarcyParams &params);

  // what a solver of this grid holds: per-cell fields and work arrays, per-column faces
  static double bytes_for(const GridGeom &geom);
  double bytes() const;

  const GridGeom &geom() const { return geom_; }
  const DarcyParams &params() const { return params_; }
  int ncells() const { return ncells_; }
  double z_grid_top() const { return geom_.zlo + geom_.nz * geom_.dz; }

  // ---- deposition: per cell sum of s*V_i and s*V_i*v_i (interleaved xyz, 3 per cell)
  std::vector<double> &solid_volume() { return solid_volume_; }
  std::vector<double> &solid_momentum() { return solid_momentum_; }
  void clear_deposits();

  // phi = clamp(1 - solid_volume/V_cell), vbar = momentum/solid_volume (0 where no
  // solid), k = Kozeny-Carman(phi). The previous phi is kept for update_dphi_dt.
  void update_porosity();
  // solid_volume now holds the deposits of the predicted positions x + v*interval:
  // dphi/dt = (phi(t+interval) - phi(t-interval)) / (2 interval); on the first update
  // (no phi(t-interval) yet) the forward difference (phi(t+interval) - phi(t))/interval.
  void update_dphi_dt(double interval);
  // Unclamped porosity range of the last update_porosity (to warn about the clamp).
  double porosity_min_unclamped() const { return porosity_min_unclamped_; }
  double porosity_max_unclamped() const { return porosity_max_unclamped_; }

  // ---- one fluid step of length dt to top pressure p_top (at t+dt). Cells whose centre
  // lies at or above z_top are inactive and held at p_top; the Dirichlet p_top sits at
  // the top face of the topmost active layer (the grid's top face by default). Never
  // throws: the result says whether CG reached the tolerance (p keeps the last iterate).
  // grad p afterwards: central differences, periodic in x/y; the ghost below the bottom
  // mirrors p (no flow) or is 2 p_bottom - p (Dirichlet), the ghost above the top active
  // layer is 2 p_top - p; inactive cells have grad p = 0.
  StepResult step(double dt, double p_top) { return step(dt, p_top, z_grid_top()); }
  StepResult step(double dt, double p_top, double z_top) { return step(dt, p_top, z_top, p_bottom_); }
  // ... with a Dirichlet bottom pressure p_bottom at t+dt (the old one is the previous
  // step's, params().p_bottom at first): Crank-Nicolson on both boundaries.
  StepResult step(double dt, double p_top, double z_top, double p_bottom);

  // ---- fields (per cell; vector fields interleaved xyz)
  const std::vector<double> &pressure() const { return pressure_; }
  const std::vector<double> &porosity() const { return porosity_; }
  const std::vector<double> &permeability() const { return permeability_; }
  const std::vector<double> &mean_velocity() const { return mean_velocity_; }
  const std::vector<double> &dphi_dt() const { return dphi_dt_; }
  std::vector<double> &dphi_dt() { return dphi_dt_; }  // the caller may set it directly
  const std::vector<double> &pressure_gradient() const { return pressure_gradient_; }
  double p_top() const { return p_top_; }
  double p_bottom() const { return p_bottom_; }
  int active_layers() const { return active_layers_; }
  const FluidBalance &balance() const { return balance_; }

  // Set p (initial value) together with the top pressure at this time, which the next
  // Crank-Nicolson step uses as its old boundary value.
  void set_pressure(const std::vector<double> &p, double p_top);
  // The same for a Dirichlet bottom whose pressure changes in time.
  void set_pressure(const std::vector<double> &p, double p_top, double p_bottom);

  // ---- restart: [nx, ny, nz, porosity_updates, p_top, active_layers, p_bottom,
  // p(ncells), phi(ncells), balance (stored, boundary, grains, allowance)], phi being that
  // of the last update_porosity (it becomes phi(t-dt) of the next central difference).
  // set_state returns false if the state is not one of this grid.
  std::vector<double> state() const;
  bool set_state(const std::vector<double> &state);
  static size_t state_size(const GridGeom &geom);

 private:
  int layers_below(double z_top) const;
  void build_coefficients(int active_layers);
  // out = div(k grad p) over the active cells, boundary values p_top and p_bottom
  // (zero boundary values give the homogeneous operator used inside CG).
  void apply_operator(const double *p, double p_top, double p_bottom, double *out) const;
  // the Crank-Nicolson system A dp = residual_ on the first m cells: CG to the tolerance,
  // or the original's relaxed sweeps; dp in update_
  void solve_converged(int m, double p_top, double p_bottom, StepResult &result);
  void solve_relaxed(int m, StepResult &result);
  void porosity_from_deposits(std::vector<double> &out) const;
  void update_permeability();
  void update_pressure_gradient();
  void add_to_balance(double dt, double p_top_mean, double p_bottom_mean, double source_sum,
                      double diag_tolerance_sum);

  GridGeom geom_;
  DarcyParams params_;
  int ncells_, nxy_;
  int active_layers_;
  int porosity_updates_ = 0;
  double p_top_ = 0.0;  // top pressure of the last step (or set_pressure)
  double p_bottom_;     // Dirichlet bottom pressure of the last step (or set_pressure)

  std::vector<double> solid_volume_, solid_momentum_;
  std::vector<double> pressure_, porosity_, porosity_previous_, porosity_next_, permeability_;
  std::vector<double> mean_velocity_, dphi_dt_, pressure_gradient_;
  double porosity_min_unclamped_ = 1.0, porosity_max_unclamped_ = 1.0;
  FluidBalance balance_;

  // per step: face coefficients k_f/Delta^2 on the +x, +y, +z face of each cell (for the
  // top active layer the Dirichlet half-cell face, 2k/dz^2), the bottom face (2k/dz^2
  // with a Dirichlet bottom, else 0) of the first layer, and CG work arrays
  std::vector<double> coef_x_, coef_y_, coef_z_, coef_bottom_, capacity_;
  std::vector<double> diag_, residual_, update_, precond_, direction_, product_;
};

}  // namespace porewater

#endif
