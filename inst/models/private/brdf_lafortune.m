## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{def} =} brdf_lafortune ()
## The isotropic Lafortune model's type definition, as @code{brdf_TYPE}
## gives the others' (see @code{model_def}): its fields, formula, the
## bounds of its lobe fields, the lobe fields of a lobe not fitted
## (@code{blank}), the reduction its fit merges samples by, the fit's
## coordinates and policy, and its files' layout (the JSON format tag, the
## text table's row names, BRDF Explorer's sliders, lobe function and
## geometry).  Its value and Jacobian are @code{lafortune_core}'s (so
## @code{lobe} is empty: the lobe has no unit amplitude to factor out).
## f = rho_d/pi + sum_k max (Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0)^e_k.
##
## @code{coords} is the fit's coordinates (@code{fit_lafortune}, as
## @code{fit_phys} is the physically based types'): values and Jacobian,
## bounds, the (a, c) grouping, the acceptance set and guard, starts, and
## the parameters in the data's units.  @code{starts} holds the candidate
## lobes the fit grows from (fit_starts): direction families and exponents.
## @code{grow} is the fit's policy (fit_driver, fit_grow): samples below
## the horizon enter the fit (the lobe is defined there), the first
## @code{tries} starts are screened on a coarse grid and the first accepted
## start ends a lobe's search, and no albedo is reported.
## @end deftypefn

function def = brdf_lafortune ()
  def = struct ("type", "lafortune", "title", "Lafortune (isotropic)",
                "fields", {{"rho_d", "Cxy", "Cz", "e"}},
                "formula", "f = rho_d/pi + sum_k max(Cxy_k*(ux*vx + uy*vy) + Cz_k*uz*vz, 0)^e_k",
                "reduce", "(ux vx + uy vy, uz vz)", "lobe", []);
  ## bounds of the lobe fields Cxy, Cz, e (as a physically based type's lo
  ## and hi bound its lobe fields ks and the shape)
  def.lo = [-Inf -Inf 0];
  def.hi = [Inf Inf 1e7];
  ## the fit's candidate lobes (fit_starts): direction families (Cxy, Cz),
  ## forward lobes from steep to flat, retro-reflective, near-normal; and
  ## exponents 1 to 1e5, two per decade
  def.starts = struct ("dirs", [-1 1; -1 0.7; -1 1.3; -1 0.4; -1 0.2; -1 2; 1 1; 0 1],
                       "expo", 10 .^ (0:0.5:5));
  ## a lobe not fitted (Cxy, Cz, e), and the fit's coordinates and policy
  def.blank = [0 0 1];
  def.coords = @fit_lafortune;
  def.grow = struct ("below", true, "screen", true, "first", true, "albedo", false);
  def.tag = "lafortune-model";
  ## the text table: the paper's names of the lobe parameters
  def.table = struct ("head", ["# Lafortune model: %s, %d lobe(s), one column per channel\n" ...
                               "# f = rho_d/pi + sum_k max(o_xy,k (ux vx + uy vy) + o_z,k uz vz, 0)^n_k\n"],
                      "labels", {{"o_xy", "o_z", "n"}});
  ## BRDF Explorer: ux vx + uy vy as dot(L,V) - dot(L,N) dot(V,N), free of the
  ## tangents X and Y (which its lit sphere leaves undefined where N = +-Y)
  def.shader = struct ("head", ["# Lafortune model '%s', %d lobe(s), exported by lafortune_export\n" ...
                                "# f = rho_d/pi + sum_k max(Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0)^e_k per channel\n\n"],
                       "lobe", ["float lobe(float cxy, float cz, float e, float sxy, float sz)\n{\n" ...
                                "    float b = cxy * sxy + cz * sz;\n" ...
                                "    return b > 0.0 ? pow(b, e) : 0.0;\n}\n\n"],
                       "geometry", ["    float ln = dot(L, N);\n" ...
                                    "    float vn = dot(V, N);\n" ...
                                    "    if (ln <= 0.0 || vn <= 0.0) return vec3(0.0);   // below the horizon, as lafortune_eval\n" ...
                                    "    // ux vx + uy vy without X and Y (BRDF Explorer's lit sphere has NaN there at N = +-Y)\n" ...
                                    "    float sxy = dot(L, V) - ln * vn;\n" ...
                                    "    float sz = ln * vn;\n"],
                       "args", {{"sxy", "sz"}}, "name", "%s%d_%s",
                       "slider", [-2 2 NaN; -2 2 NaN; 0 100 NaN]);
endfunction
