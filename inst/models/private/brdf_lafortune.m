## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{def} =} brdf_lafortune ()
## The isotropic Lafortune model's type definition, as @code{brdf_TYPE}
## gives the others' (see @code{model_def}): its fields, formula, the
## bounds of its lobe fields, the reduction its fit merges samples by, the
## fit's coordinates, and its files' layout (the JSON format tag, the text
## table's row names, BRDF Explorer's sliders, lobe function and geometry).
## Its value and Jacobian are @code{lafortune_core}'s (so @code{lobe} is
## empty: the lobe has no unit amplitude to factor out); its fit is
## @code{fit_lafortune}.
## f = rho_d/pi + sum_k max (Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0)^e_k.
##
## @code{coords} is the fit's coordinates, as @code{fit_phys} is the
## physically based types': @code{coords ("eval", @var{D}, @var{p})} the
## values (and Jacobian) at the groups (a, c) = @code{D.x} of one channel's
## parameters [rho_d; Cxy; Cz; e; ...] (lafortune_core), or with
## @code{D.nch} > 1 of lobes shared across the channels
## (@code{shared_lobes}, the shared-colour parameters); @code{coords
## ("bounds", @var{D}, @var{np})} their bounds: rho_d >= 0 and each lobe
## field within @code{lo} and @code{hi} (the exponent in [0, 1e7]);
## @code{coords ("x", [], @var{S})} what the model sees of each pair of the
## table @var{S}, (a, c) = (ux vx + uy vy, uz vz): the fit merges samples
## equal in it; @code{coords ("unscale", @var{D}, @var{p}, @var{s})}
## parameters fitted to data divided by @var{s} in the data's units: rho_d
## times @var{s}, each lobe's Cxy and Cz times @var{s}^(1/e) (a lobe with e
## = 0, a step, cannot be scaled and stays), so that the model is @var{s}
## times the fitted one; shared lobes (@code{D.nch} > 1) by
## @code{shared_lobes}.  @code{starts} holds the candidate lobes the fit
## grows from (fit_starts): direction families and exponents.
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
  def.coords = @coords;
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

## the fit's coordinates (see above)
function varargout = coords (what, D, arg, s)
  switch (what)
    case "x"
      S = arg;
      varargout = {[S.wi(:,1) .* S.wo(:,1) + S.wi(:,2) .* S.wo(:,2), S.wi(:,3) .* S.wo(:,3)]};
    case "unscale"
      if (isempty (D) || D.nch == 1)
        varargout = {unscale(arg, s)};
      else
        varargout = {shared_lobes("unscale", arg, s, D.ref, D.nch)};
      endif
    case "eval"
      if (D.nch == 1)
        [varargout{1:max (nargout, 1)}] = __lafortune_lafortune_core__ (arg, D.x(:,1), D.x(:,2));
      else
        [varargout{1:max (nargout, 1)}] = shared_lobes ("eval", arg, D.ref, D.nch, D.x(:,1), D.x(:,2));
      endif
    case "bounds"
      if (D.nch == 1)
        nl = (arg - 1) / 3;
        def = D.def;
        varargout = {[0; repmat(def.lo(:), nl, 1)], [Inf; repmat(def.hi(:), nl, 1)]};
      else
        [varargout{1:2}] = shared_lobes ("bounds", arg, D.nch);
      endif
  endswitch
endfunction

## one channel's parameters P fitted to data divided by S, in the data's units
function p = unscale (p, s)
  if (s == 1)
    return;
  endif
  p(1) *= s;
  for k = 1:(numel (p) - 1) / 3
    e = p(3*k+1);
    f = exp (log (s) / e);
    if (e > 0 && isfinite (f) && f > 0)
      p(3*k-1:3*k) *= f;
    endif
  endfor
endfunction
