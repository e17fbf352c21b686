#include "darcy/solver.h"

#include <algorithm>
#include <cmath>

namespace porewater {

DarcySolver::DarcySolver(const GridGeom &geom, const DarcyParams &params) :
    geom_(geom), params_(params), ncells_(cell_count(geom)), nxy_(geom.nx * geom.ny),
    active_layers_(geom.nz), p_bottom_(params.p_bottom)
{
  const size_t n = ncells_;
  solid_volume_.assign(n, 0.0);
  solid_momentum_.assign(3 * n, 0.0);
  pressure_.assign(n, 0.0);
  // no grains deposited yet: phi = 1, clamped
  porosity_.assign(n, clamp_porosity(1.0, params_.porosity_min, params_.porosity_max));
  porosity_previous_ = porosity_;
  porosity_next_.assign(n, 0.0);
  permeability_.assign(n, 0.0);
  mean_velocity_.assign(3 * n, 0.0);
  dphi_dt_.assign(n, 0.0);
  pressure_gradient_.assign(3 * n, 0.0);
  for (auto *v : {&coef_x_, &coef_y_, &coef_z_, &capacity_, &diag_, &residual_, &update_,
                  &precond_, &direction_, &product_})
    v->assign(n, 0.0);
  coef_bottom_.assign(nxy_, 0.0);
  update_permeability();
}

// ---------------------------------------------------------------- memory

namespace {
// the per-cell arrays of the constructor: 16 values of fields (vector fields 3 each), 10 of
// coefficients and CG work; and one bottom-face coefficient per column
const int DOUBLES_PER_CELL = 1 + 3 + 1 + 1 + 1 + 1 + 1 + 3 + 1 + 3 + 10;
}    // namespace

double DarcySolver::bytes_for(const GridGeom &geom)
{
  return sizeof(double) * (DOUBLES_PER_CELL * (double) cell_count(geom) + (double) geom.nx * geom.ny);
}

double DarcySolver::bytes() const
{
  size_t doubles = 0;
  for (const std::vector<double> *v :
       {&solid_volume_, &solid_momentum_, &pressure_, &porosity_, &porosity_previous_,
        &porosity_next_, &permeability_, &mean_velocity_, &dphi_dt_, &pressure_gradient_,
        &coef_x_, &coef_y_, &coef_z_, &capacity_, &diag_, &residual_, &update_, &precond_,
        &direction_, &product_, &coef_bottom_})
    doubles += v->capacity();
  return sizeof(double) * (double) doubles;
}

// ---------------------------------------------------------------- deposition, porosity

void DarcySolver::clear_deposits()
{
  std::fill(solid_volume_.begin(), solid_volume_.end(), 0.0);
  std::fill(solid_momentum_.begin(), solid_momentum_.end(), 0.0);
}

void DarcySolver::porosity_from_deposits(std::vector<double> &out) const
{
  const double volume = cell_volume(geom_);
  for (int c = 0; c < ncells_; ++c)
    out[c] = clamp_porosity(1.0 - solid_volume_[c] / volume, params_.porosity_min,
                            params_.porosity_max);
}

void DarcySolver::update_porosity()
{
  if (porosity_updates_ > 0) porosity_previous_.swap(porosity_);  // keep phi(t - dt)
  const double volume = cell_volume(geom_);
  porosity_min_unclamped_ = 1.0;
  porosity_max_unclamped_ = 0.0;
  for (int c = 0; c < ncells_; ++c) {
    const double raw = 1.0 - solid_volume_[c] / volume;
    porosity_min_unclamped_ = std::min(porosity_min_unclamped_, raw);
    porosity_max_unclamped_ = std::max(porosity_max_unclamped_, raw);
    porosity_[c] = clamp_porosity(raw, params_.porosity_min, params_.porosity_max);
    const double solid = solid_volume_[c];
    for (int d = 0; d < 3; ++d)
      mean_velocity_[3 * c + d] = solid > 0.0 ? solid_momentum_[3 * c + d] / solid : 0.0;
  }
  update_permeability();
  ++porosity_updates_;
}

void DarcySolver::update_dphi_dt(double interval)
{
  porosity_from_deposits(porosity_next_);
  const bool central = porosity_updates_ >= 2;  // phi(t - interval) known
  const std::vector<double> &before = central ? porosity_previous_ : porosity_;
  const double span = central ? 2.0 * interval : interval;
  for (int c = 0; c < ncells_; ++c) dphi_dt_[c] = (porosity_next_[c] - before[c]) / span;
}

void DarcySolver::update_permeability()
{
  for (int c = 0; c < ncells_; ++c)
    permeability_[c] = kozeny_carman(porosity_[c], params_.kc, params_.kmax);
}

// ---------------------------------------------------------------- discrete operator

int DarcySolver::layers_below(double z_top) const
{
  // layer k is active when its centre zlo + (k+1/2) dz lies strictly below z_top
  const double last = (z_top - geom_.zlo) / geom_.dz - 0.5;
  if (!(last > 0.0)) return 0;
  return std::min(geom_.nz, (int) std::ceil(last));
}

void DarcySolver::build_coefficients(int layers)
{
  const GridGeom &g = geom_;
  const double cx = 1.0 / (g.dx * g.dx), cy = 1.0 / (g.dy * g.dy), cz = 1.0 / (g.dz * g.dz);
  const std::vector<double> &k = permeability_;
  for (int kz = 0; kz < layers; ++kz)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int c = cell_index(g, i, j, kz);
        // a single periodic cell couples only to itself: no flux
        const int xp = cell_index(g, (i + 1) % g.nx, j, kz);
        const int yp = cell_index(g, i, (j + 1) % g.ny, kz);
        coef_x_[c] = g.nx > 1 ? cx * harmonic_mean(k[c], k[xp]) : 0.0;
        coef_y_[c] = g.ny > 1 ? cy * harmonic_mean(k[c], k[yp]) : 0.0;
        if (kz < layers - 1)
          coef_z_[c] = cz * harmonic_mean(k[c], k[c + nxy_]);
        else  // half-cell face to the Dirichlet top, face permeability of the active cell
          coef_z_[c] = params_.top == DarcyParams::Top::Dirichlet ? 2.0 * cz * k[c] : 0.0;
        if (kz == 0)
          coef_bottom_[c] =
              params_.bottom == DarcyParams::Bottom::Dirichlet ? 2.0 * cz * k[c] : 0.0;
      }
}

void DarcySolver::apply_operator(const double *p, double p_top, double p_bottom,
                                 double *out) const
{
  const GridGeom &g = geom_;
  for (int kz = 0; kz < active_layers_; ++kz)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int c = cell_index(g, i, j, kz);
        const int xm = cell_index(g, wrap_index(i - 1, g.nx), j, kz);
        const int xp = cell_index(g, wrap_index(i + 1, g.nx), j, kz);
        const int ym = cell_index(g, i, wrap_index(j - 1, g.ny), kz);
        const int yp = cell_index(g, i, wrap_index(j + 1, g.ny), kz);
        double sum = coef_x_[c] * (p[xp] - p[c]) + coef_x_[xm] * (p[xm] - p[c]) +
            coef_y_[c] * (p[yp] - p[c]) + coef_y_[ym] * (p[ym] - p[c]);
        sum += kz > 0 ? coef_z_[c - nxy_] * (p[c - nxy_] - p[c])
                      : coef_bottom_[c] * (p_bottom - p[c]);
        sum += kz < active_layers_ - 1 ? coef_z_[c] * (p[c + nxy_] - p[c])
                                       : coef_z_[c] * (p_top - p[c]);
        out[c] = sum;
      }
}

// ---------------------------------------------------------------- time step

StepResult DarcySolver::step(double dt, double p_top, double z_top, double p_bottom_new)
{
  const GridGeom &g = geom_;
  active_layers_ = layers_below(z_top);
  const int m = active_layers_ * nxy_;  // active cells are the first m flat indices
  build_coefficients(active_layers_);
  const double mu = params_.viscosity, beta = params_.compressibility;
  const bool bottom_dirichlet = params_.bottom == DarcyParams::Bottom::Dirichlet;
  const double p_bottom = bottom_dirichlet ? p_bottom_new : 0.0;
  const double p_bottom_old = bottom_dirichlet ? p_bottom_ : 0.0;

  // Solve A dp = r0 for dp = p(t+dt) - p(t) (CG warm-started from p(t)), with
  // A = beta phi mu/dt - L0/2 and r0 = b - A p(t) = L p(t) - grain forcing, where the
  // boundary terms of L are the means of old and new p_top, p_bottom (Crank-Nicolson).
  apply_operator(pressure_.data(), 0.5 * (p_top_ + p_top), 0.5 * (p_bottom_old + p_bottom),
                 residual_.data());
  const double *phi = porosity_.data();
  double source_sum = 0.0, diag_sum = 0.0;  // for the balance: sum of the two per cell
  for (int kz = 0; kz < active_layers_; ++kz)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int c = cell_index(g, i, j, kz);
        const int xm = cell_index(g, wrap_index(i - 1, g.nx), j, kz);
        const int ym = cell_index(g, i, wrap_index(j - 1, g.ny), kz);
        // grad phi: central, zero gradient (mirrored ghost) at the bottom and at the top
        // active layer's Dirichlet face: the cell beyond that face is outside the bed the
        // fluid is solved in (it holds the wall and the void above), so its phi is not the
        // bed's; mirror it as at the impermeable bottom
        const int below = kz > 0 ? c - nxy_ : c, above = kz < active_layers_ - 1 ? c + nxy_ : c;
        const double grad_phi[3] = {
            (phi[cell_index(g, wrap_index(i + 1, g.nx), j, kz)] - phi[xm]) / (2.0 * g.dx),
            (phi[cell_index(g, i, wrap_index(j + 1, g.ny), kz)] - phi[ym]) / (2.0 * g.dy),
            (phi[above] - phi[below]) / (2.0 * g.dz)};
        const double *v = &mean_velocity_[3 * c];
        const double material_dphi =
            dphi_dt_[c] + v[0] * grad_phi[0] + v[1] * grad_phi[1] + v[2] * grad_phi[2];
        const double source = -material_dphi / (1.0 - phi[c]);
        residual_[c] += mu * source;  // row scaled by beta phi mu
        source_sum += source;
        capacity_[c] = beta * phi[c] * mu / dt;
        const double faces = coef_x_[c] + coef_x_[xm] + coef_y_[c] + coef_y_[ym] + coef_z_[c] +
            (kz > 0 ? coef_z_[c - nxy_] : coef_bottom_[c]);
        diag_[c] = capacity_[c] + 0.5 * faces;
        diag_sum += diag_[c];
      }
  std::fill(update_.begin(), update_.begin() + m, 0.0);
  StepResult result{false, 0, 0.0, 0.0, -1};
  double allowance = 0.0;
  if (params_.scheme == DarcyParams::Scheme::Relaxed) {
    solve_relaxed(m, result);
    // the sweeps leave the Crank-Nicolson rows unsolved by r = r0 - A dp: that is the
    // balance residual's allowance (row c times V dt/mu), not a tolerance
    apply_operator(update_.data(), 0.0, 0.0, product_.data());
    for (int c = 0; c < m; ++c)
      allowance += std::fabs(residual_[c] - (capacity_[c] * update_[c] - 0.5 * product_[c]));
  } else {
    solve_converged(m, p_top, p_bottom, result);
    allowance = diag_sum * result.tolerance;
  }

  add_to_balance(dt, 0.5 * (p_top_ + p_top), 0.5 * (p_bottom_old + p_bottom), source_sum,
                 allowance);
  // keep the best iterate even when not converged; the caller decides what to do
  for (int c = 0; c < m; ++c) pressure_[c] += update_[c];
  for (int c = m; c < ncells_; ++c) pressure_[c] = p_top;
  p_top_ = p_top;
  p_bottom_ = p_bottom_new;
  update_pressure_gradient();
  return result;
}

// Jacobi-preconditioned CG on A dp = r0 (residual_ holds r0, then r), warm-started at dp = 0
void DarcySolver::solve_converged(int m, double p_top, double p_bottom, StepResult &result)
{
  // Jacobi-preconditioned residual and convergence test, max|r_i/A_ii| <= tolerance
  auto converged = [&]() {
    double scale = std::max(std::fabs(p_top), std::fabs(p_bottom));
    bool finite = true;
    result.residual = 0.0;
    result.worst_cell = -1;
    for (int c = 0; c < m; ++c) {
      precond_[c] = residual_[c] / diag_[c];
      const double size = std::fabs(precond_[c]);
      if (finite && !std::isfinite(precond_[c])) finite = false, result.worst_cell = c;
      if (finite && size > result.residual) result.residual = size, result.worst_cell = c;
      scale = std::max(scale, std::fabs(pressure_[c] + update_[c]));
    }
    if (!finite) result.residual = NAN;  // std::max hides NaN: report it
    result.tolerance = params_.tol_abs + params_.tol_rel * scale;
    return finite && result.residual <= result.tolerance;
  };
  auto dot = [m](const std::vector<double> &a, const std::vector<double> &b) {
    double sum = 0.0;
    for (int c = 0; c < m; ++c) sum += a[c] * b[c];
    return sum;
  };

  result.converged = converged();
  if (!result.converged) {
    direction_ = precond_;
    double rz = dot(residual_, precond_);
    while (result.iterations < params_.maxiter) {
      ++result.iterations;
      apply_operator(direction_.data(), 0.0, 0.0, product_.data());
      for (int c = 0; c < m; ++c)
        product_[c] = capacity_[c] * direction_[c] - 0.5 * product_[c];
      const double curvature = dot(direction_, product_);
      if (!(curvature > 0.0)) break;  // breakdown: A is SPD, so only round-off gets here
      const double alpha = rz / curvature;
      for (int c = 0; c < m; ++c) {
        update_[c] += alpha * direction_[c];
        residual_[c] -= alpha * product_[c];
      }
      if ((result.converged = converged())) break;
      const double rz_new = dot(residual_, precond_);
      const double beta_cg = rz_new / rz;
      rz = rz_new;
      for (int c = 0; c < m; ++c) direction_[c] = precond_[c] + beta_cg * direction_[c];
    }
  }

}

// The original program's iteration (sphere, darcy.cuh): each sweep takes the fixed-point
// value of Crank-Nicolson at the last iterate, p* = p_old + (r0 + L0 dp/2)/C (explicit
// half of the old and of the iterate), and relaxes toward it, dp <- (1-theta) dp +
// theta (p* - p_old); it stops when the largest |p_new - p_iter|/|p_iter| is at most
// relaxed_tol, tested at sweep 0 and every 10th. With |p| large that is after one sweep.
// (sphere's src/darcy.cuh, jacobiIterationDarcy, and src/device.cu: theta 0.05, the norm
// tested every nijacnorm = 10 sweeps.)
void DarcySolver::solve_relaxed(int m, StepResult &result)
{
  const double theta = params_.theta;
  result.tolerance = params_.relaxed_tol;
  for (int sweep = 0; sweep < params_.maxiter; ++sweep) {
    apply_operator(update_.data(), 0.0, 0.0, product_.data());
    double largest = 0.0;
    int worst = -1;
    bool finite = true;
    for (int c = 0; c < m; ++c) {
      const double fixed_point = (residual_[c] + 0.5 * product_[c]) / capacity_[c];
      const double relaxed = (1.0 - theta) * update_[c] + theta * fixed_point;
      // as sphere: (p_new - p_iter)/(p_iter + 1e-16), pressure in the input's units
      const double relative = std::fabs((relaxed - update_[c]) / (pressure_[c] + update_[c] + 1e-16));
      if (finite && !std::isfinite(relaxed)) finite = false, worst = c;
      if (finite && relative > largest) largest = relative, worst = c;
      direction_[c] = relaxed;
    }
    std::swap(update_, direction_);
    result.iterations = sweep + 1;
    result.residual = finite ? largest : NAN;
    result.worst_cell = worst;
    if (!finite) return;
    if (sweep % 10 == 0 && largest <= result.tolerance) {
      result.converged = true;
      return;
    }
  }
}

// Before p += dp: the terms of each row times V_cell dt/mu (see FluidBalance), with the
// Crank-Nicolson face values p_face (means of old and new) and p_c + dp/2.
void DarcySolver::add_to_balance(double dt, double p_top_mean, double p_bottom_mean,
                                 double source_sum, double diag_tolerance_sum)
{
  const double volume = cell_volume(geom_), beta = params_.compressibility;
  const int m = active_layers_ * nxy_, top_layer = (active_layers_ - 1) * nxy_;
  double stored = 0.0, inflow = 0.0;
  for (int c = 0; c < m; ++c) stored += beta * porosity_[c] * update_[c];
  auto mean_p = [&](int c) { return pressure_[c] + 0.5 * update_[c]; };
  if (active_layers_ > 0)
    for (int c = 0; c < nxy_; ++c)  // coefficients are 0 at a no-flow face
      inflow += coef_z_[top_layer + c] * (p_top_mean - mean_p(top_layer + c)) +
          coef_bottom_[c] * (p_bottom_mean - mean_p(c));
  const double scale = volume * dt / params_.viscosity;
  balance_.stored += volume * stored;
  balance_.boundary += scale * inflow;
  balance_.grains += volume * dt * source_sum;
  balance_.allowance += scale * diag_tolerance_sum;
}

// ---------------------------------------------------------------- pressure gradient

void DarcySolver::update_pressure_gradient()
{
  const GridGeom &g = geom_;
  const double *p = pressure_.data();
  const bool bottom_dirichlet = params_.bottom == DarcyParams::Bottom::Dirichlet;
  const bool top_dirichlet = params_.top == DarcyParams::Top::Dirichlet;
  std::fill(pressure_gradient_.begin(), pressure_gradient_.end(), 0.0);  // inactive: 0
  for (int kz = 0; kz < active_layers_; ++kz)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int c = cell_index(g, i, j, kz);
        // ghost values: mirror (zero normal gradient) at a no-flow face, 2 p_face - p at
        // a Dirichlet face
        double below = p[c], above = p[c];
        if (kz > 0) below = p[c - nxy_];
        else if (bottom_dirichlet) below = 2.0 * p_bottom_ - p[c];
        if (kz < active_layers_ - 1) above = p[c + nxy_];
        else if (top_dirichlet) above = 2.0 * p_top_ - p[c];
        double *grad = &pressure_gradient_[3 * c];
        grad[0] = (p[cell_index(g, wrap_index(i + 1, g.nx), j, kz)] -
                   p[cell_index(g, wrap_index(i - 1, g.nx), j, kz)]) / (2.0 * g.dx);
        grad[1] = (p[cell_index(g, i, wrap_index(j + 1, g.ny), kz)] -
                   p[cell_index(g, i, wrap_index(j - 1, g.ny), kz)]) / (2.0 * g.dy);
        grad[2] = (above - below) / (2.0 * g.dz);
      }
}

void DarcySolver::set_pressure(const std::vector<double> &p, double p_top)
{
  set_pressure(p, p_top, p_bottom_);
}

void DarcySolver::set_pressure(const std::vector<double> &p, double p_top, double p_bottom)
{
  std::copy(p.begin(), p.begin() + std::min<size_t>(p.size(), ncells_), pressure_.begin());
  p_top_ = p_top;
  p_bottom_ = p_bottom;
  update_pressure_gradient();
}

// ---------------------------------------------------------------- restart

std::vector<double> DarcySolver::state() const
{
  std::vector<double> s = {double(geom_.nx),         double(geom_.ny), double(geom_.nz),
                           double(porosity_updates_), p_top_,           double(active_layers_),
                           p_bottom_};
  s.insert(s.end(), pressure_.begin(), pressure_.end());
  s.insert(s.end(), porosity_.begin(), porosity_.end());
  s.insert(s.end(), {balance_.stored, balance_.boundary, balance_.grains, balance_.allowance});
  return s;
}

size_t DarcySolver::state_size(const GridGeom &geom)
{
  return 7 + 2 * size_t(cell_count(geom)) + 4;
}

bool DarcySolver::set_state(const std::vector<double> &s)
{
  const size_t header = 7, fields_end = header + 2 * size_t(ncells_);
  if (s.size() != state_size(geom_) || int(s[0]) != geom_.nx || int(s[1]) != geom_.ny ||
      int(s[2]) != geom_.nz)
    return false;
  porosity_updates_ = int(s[3]);
  p_top_ = s[4];
  active_layers_ = std::max(0, std::min(geom_.nz, int(s[5])));
  p_bottom_ = s[6];
  std::copy(s.begin() + header, s.begin() + header + ncells_, pressure_.begin());
  std::copy(s.begin() + header + ncells_, s.begin() + fields_end, porosity_.begin());
  balance_ = FluidBalance{s[fields_end], s[fields_end + 1], s[fields_end + 2], s[fields_end + 3]};
  update_permeability();
  update_pressure_gradient();
  return true;
}

}  // namespace porewater
