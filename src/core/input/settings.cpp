#include "input/settings.h"
#include "run/progress.h"
#include <cmath>

namespace porewater {

LinearCoulombSettings parse_linear_coulomb(KeywordReader &in)
{
  LinearCoulombSettings s;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "lever")
      s.lever = in.choice({"contact", "radius"}) == 0 ? LEVER_CONTACT : LEVER_RADIUS;
    else if (key == "dissipation")
      s.dissipation = in.yes_no();
    else if (key == "overlap_limit")
      s.overlap_limit = in.at_most(2.0);
    else
      in.unknown_keyword({"lever", "dissipation", "overlap_limit"});
  }
  return s;
}

ContactCoeffs parse_linear_coulomb_coeffs(KeywordReader &in)
{
  if (in.remaining() != 3) in.fail("expected I J kn kt mu");
  const double kn = in.named("kn").positive();
  const double kt = in.named("kt").non_negative();
  const double mu = in.named("mu").non_negative();
  return contact_coeffs(kn, kt, mu);
}

WallStressSettings parse_wall_stress(KeywordReader &in)
{
  WallStressSettings s;
  bool have_z = false, have_stress = false, have_mass = false, have_kn = false;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "z") {
      s.z_auto = in.accept("auto");
      if (!s.z_auto) s.z = in.number("auto");
      have_z = true;
    } else if (key == "stress") {
      s.stress = in.number_or_variable();
      have_stress = true;
    } else if (key == "mass") {
      s.mass = in.positive();
      have_mass = true;
    } else if (key == "kn") {
      s.kn = in.positive();
      have_kn = true;
    } else if (key == "damping") {
      s.damping = in.non_negative();
    } else if (key == "damping_velocity") {
      s.damping_velocity = in.choice({"relative", "absolute"});
    } else if (key == "plate_damping") {
      s.plate_damping = in.non_negative();
    } else if (key == "variables") {
      s.variables_read_atoms = in.choice({"atoms", "global"}) == 0;
    } else {
      in.unknown_keyword({"z", "stress", "mass", "kn", "damping", "damping_velocity",
                          "plate_damping", "variables"});
    }
  }
  in.require({"z", "stress", "mass", "kn"}, {have_z, have_stress, have_mass, have_kn});
  return s;
}

ShearStressSettings parse_shear_stress(KeywordReader &in)
{
  ShearStressSettings s;
  bool have_tau = false, have_mass = false;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "tau") {
      s.tau = in.number();
      have_tau = true;
    } else if (key == "mass") {
      s.mass = in.positive();
      have_mass = true;
    } else {
      in.unknown_keyword({"tau", "mass"});
    }
  }
  in.require({"tau", "mass"}, {have_tau, have_mass});
  return s;
}

BedSettings parse_nve_sphere_bed(KeywordReader &in)
{
  BedSettings s;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "held") {
      s.held_group = in.word("a group ID");
    } else if (key == "gravity") {
      s.gravity = in.number();
      s.gravity_group = in.named("gravity group").word("a group ID");
    } else if (key == "floor") {
      s.z_floor = in.number();
      s.kn = in.named("floor kn").positive();
      s.floor = true;
    } else if (key == "fuse") {
      s.fuse = in.yes_no();
    } else {
      in.unknown_keyword({"held", "gravity", "floor", "fuse"});
    }
  }
  return s;
}

ProgressSettings parse_progress(KeywordReader &in)
{
  ProgressSettings s;
  bool have_end = false;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "end") {
      const double step = in.non_negative();
      if (step != std::floor(step) || step > 9.0e18) in.fail("end expects a step number (an integer >= 0)");
      s.end_step = (long long) step;
      have_end = true;
    } else if (key == "period") {
      s.period = in.positive();
    } else if (key == "walltime") {
      const std::string text = in.word("HH:MM:SS, MM:SS, seconds or none");
      s.walltime = text == "none" ? 0.0 : parse_wall_time(text);
      if (text != "none" && !(s.walltime > 0.0))
        in.fail("walltime expects HH:MM:SS, MM:SS, seconds (> 0) or none, got '" + text + "'");
    } else if (key == "safety") {
      s.safety = in.non_negative();
    } else {
      in.unknown_keyword({"end", "period", "walltime", "safety"});
    }
  }
  in.require({"end"}, {have_end});
  return s;
}

PrintEverySettings parse_print_every(KeywordReader &in)
{
  PrintEverySettings s;
  s.every = in.named("N").count();
  s.text = in.named("text").word("a string");
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "file" || key == "append") {
      s.append = key == "append";
      s.file = in.word("a file name");
    } else if (key == "screen") {
      s.screen = in.yes_no();
    } else if (key == "title") {
      s.title = in.word("a string");
      s.title_given = true;
    } else {
      in.unknown_keyword({"file", "append", "screen", "title"});
    }
  }
  return s;
}

Ty3Settings parse_ty3(KeywordReader &in)
{
  Ty3Settings s;
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "corrector")
      s.corrector = in.yes_no();
    else
      in.unknown_keyword({"corrector"});
  }
  return s;
}

DarcySettings parse_darcy(KeywordReader &in, double box_zlo, double box_zhi)
{
  DarcySettings s;
  s.zhi = box_zhi;
  bool have_grid = false, have_viscosity = false, have_beta = false, have_density = false,
       have_kc = false;
  // `top`/`bottom`: noflow or a pressure (constant or v_name)
  auto boundary = [&in](NumberOrVariable &value) {
    if (in.accept("noflow")) return false;
    value = in.number_or_variable("noflow");
    return true;
  };
  while (!in.done()) {
    const std::string &key = in.keyword();
    if (key == "grid") {
      for (int &n : s.grid) n = in.count();
      have_grid = true;
    } else if (key == "viscosity") {
      s.params.viscosity = in.positive();
      have_viscosity = true;
    } else if (key == "compressibility") {
      s.params.compressibility = in.positive();
      have_beta = true;
    } else if (key == "density") {
      s.density = in.non_negative();
      have_density = true;
    } else if (key == "permeability") {
      s.params.kc = in.positive();
      have_kc = true;
    } else if (key == "top") {
      s.top = NumberOrVariable();    // noflow: 0, the value cells above ztop hold
      s.top_dirichlet = boundary(s.top);
    } else if (key == "ztop") {
      s.z_top = in.number_or_variable();
      s.z_top_given = true;
    } else if (key == "bottom") {
      s.bottom = NumberOrVariable();
      s.bottom_dirichlet = boundary(s.bottom);
    } else if (key == "initial") {
      s.initial_pressure = in.number();
    } else if (key == "gravity") {
      for (double &g : s.gravity) g = in.number();
      s.gravity_given = true;
    } else if (key == "porosity") {
      s.params.porosity_min = in.positive();
      s.params.porosity_max = in.positive();
      if (!(s.params.porosity_min <= s.params.porosity_max && s.params.porosity_max < 1.0))
        in.fail("porosity MIN MAX needs 0 < MIN <= MAX < 1");
    } else if (key == "kmax") {
      s.params.kmax = in.positive();
    } else if (key == "tol") {
      s.params.tol_rel = in.positive();
    } else if (key == "atol") {
      s.params.tol_abs = in.non_negative();
    } else if (key == "maxiter") {
      s.params.maxiter = in.count();
    } else if (key == "solver") {
      if (in.choice({"converged", "relaxed"}) == 1) {
        s.params.scheme = DarcyParams::Scheme::Relaxed;
        s.params.theta = in.at_most(1.0);
        s.params.relaxed_tol = in.positive();
      } else {
        s.params.scheme = DarcyParams::Scheme::Converged;
      }
    } else if (key == "novertical") {
      s.novertical_group = in.word("a group ID");
    } else if (key == "seepage") {
      s.seepage = in.choice({"pressure", "full"}) == 0 ? SEEPAGE_PRESSURE : SEEPAGE_FULL;
    } else if (key == "every") {
      s.every = in.count();
    } else if (key == "variables") {
      s.variables_read_atoms = in.choice({"atoms", "global"}) == 0;
    } else if (key == "interpolate") {
      s.interpolate_every_step = in.choice({"step", "fluid"}) == 0;
    } else if (key == "zhi") {
      s.zhi = in.number();
      if (!(s.zhi > box_zlo)) in.fail("zhi must lie above the box bottom");
    } else if (key == "profile") {
      s.profile_every = in.count();
      s.profile_path = in.word("a file name");
    } else if (key == "append") {
      s.profile_append = in.yes_no();
    } else if (key == "vtk") {
      s.vtk_every = in.count();
      s.vtk_prefix = in.word("a file name prefix");
    } else {
      in.unknown_keyword({"grid", "viscosity", "compressibility", "density", "permeability",
                          "top", "ztop", "bottom", "initial", "gravity", "porosity", "kmax",
                          "tol", "atol", "maxiter", "solver", "novertical", "seepage", "every",
                          "interpolate", "zhi", "profile", "append", "vtk", "variables"});
    }
  }
  in.require({"grid", "viscosity", "compressibility", "density", "permeability"},
             {have_grid, have_viscosity, have_beta, have_density, have_kc});
  if (!(s.zhi > box_zlo)) in.fail("the box top must lie above its bottom for the grid");
  s.params.bottom = s.bottom_dirichlet ? DarcyParams::Bottom::Dirichlet : DarcyParams::Bottom::NoFlow;
  s.params.top = s.top_dirichlet ? DarcyParams::Top::Dirichlet : DarcyParams::Top::NoFlow;
  return s;
}

}    // namespace porewater
