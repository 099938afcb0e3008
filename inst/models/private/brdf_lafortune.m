## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{def} =} brdf_lafortune ()
## The isotropic Lafortune model's type definition, as @code{brdf_TYPE}
## gives the others' (see @code{model_def}): its fields, formula, the
## reduction its fit merges samples by, and its files' layout (the JSON
## format tag, the text table's row names, BRDF Explorer's sliders, lobe
## function and geometry).  Its value and Jacobian are
## @code{lafortune_core}'s (so @code{lobe} is empty: the lobe has no unit
## amplitude to factor out); its fit is @code{fit_lafortune}.
## f = rho_d/pi + sum_k max (Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0)^e_k.
## @end deftypefn

function def = brdf_lafortune ()
  def = struct ("type", "lafortune", "title", "Lafortune (isotropic)",
                "fields", {{"rho_d", "Cxy", "Cz", "e"}},
                "formula", "f = rho_d/pi + sum_k max(Cxy_k*(ux*vx + uy*vy) + Cz_k*uz*vz, 0)^e_k",
                "reduce", "(ux vx + uy vy, uz vz)", "lobe", []);
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
