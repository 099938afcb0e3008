## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} model_def (@var{type})
## @deftypefnx {} {@var{types} =} model_def ()
## The definition of an analytic model type: the list of types, or the
## struct of @var{type} (@code{"lafortune"} or a physically based model
## whose lobe is defined in its own file @code{brdf_TYPE.m}).
##
## Every type has @code{type}, @code{title}, @code{fields} (the model
## struct's parameter fields, each NLOBES x 3 but @code{rho_d}, 1 x 3),
## @code{formula} and @code{reduce} (what the model sees of a pair of
## directions: the fit merges samples equal in it).  A physically based
## type (@code{def.lobe}: [g, dg] = lobe (X, q), of unit amplitude) also
## has @code{shape} (its shape parameters' names), @code{lo}, @code{hi}
## (bounds of [ks, shape]), @code{scale} ("log" or "lin" per shape
## parameter: how the fit moves it), @code{starts} (candidate values per
## shape parameter), @code{width} (the lobe's angular width in radians,
## for quadrature) and @code{glsl} (the lobe in GLSL, from ch, cd, t2, s5,
## hh, ci, co and its parameters, for BRDF Explorer).
## @end deftypefn

function def = model_def (type)
  persistent defs = struct ();
  TYPES = {"lafortune", "blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"};
  if (nargin == 0)
    def = TYPES;
    return;
  endif
  if (! ischar (type) || ! any (strcmp (type, TYPES)))
    error ("lafortune:badModelType", "unknown model type '%s'; expected one of %s",
           arg_str (type), strjoin (TYPES, ", "));
  endif
  if (isfield (defs, type))
    def = defs.(type);
    return;
  endif
  if (strcmp (type, "lafortune"))
    def = struct ("type", "lafortune", "title", "Lafortune (isotropic)",
                  "fields", {{"rho_d", "Cxy", "Cz", "e"}},
                  "formula", "f = rho_d/pi + sum_k max(Cxy_k*(ux*vx+uy*vy) + Cz_k*uz*vz, 0)^e_k",
                  "reduce", "(ux vx + uy vy, uz vz)", "lobe", []);
  else
    def = feval (["brdf_" type]);
    def.fields = [{"rho_d", "ks"}, def.shape];
    def.formula = ["f = rho_d/pi + sum_k " def.formula];
    def.reduce = "(cos theta_i, cos theta_o, wi.wo)";
    def.lobe = str2func (["brdf_" type]);
  endif
  defs.(type) = def;
endfunction
