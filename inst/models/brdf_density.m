## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{D} =} brdf_density (@var{material})
## @deftypefnx {lafortune} {[@var{D}, @var{model}] =} brdf_density (@var{material})
## The density by which directions toward the light are drawn for a
## material: what @code{brdf_sample} draws from and @code{brdf_pdf}
## evaluates, and what @code{rt_render} combines with the light's own
## samples (multiple importance sampling).
##
## @var{material} is an analytic model of any type (@code{brdf_model}):
## its own lobes are the density.  For a MERL material (@code{merl_read})
## the density is a fit of it: the model in its field @code{sampler} when
## it has one (the pipeline puts its general fit there), else a fit made
## for sampling, 2 Lafortune lobes fitted with the log weighting to 20000
## samples of the hemisphere (@code{merl_samples} without views).  Keep
## @var{model} (the second output) in @code{material.sampler} to make it
## once per material.
##
## @var{D} is a struct for @code{brdf_sample} and @code{brdf_pdf}: the
## density's parts that do not depend on the view, prepared once; its field
## @code{model} is the model it follows.
##
## Errors: @code{lafortune:badMaterial} (neither a model nor MERL data),
## and the @code{lafortune:badModel} errors of a malformed model (among
## them non-finite or negative parameters: no density can be made of it).
##
## @example
## @group
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [50 50 50]);
## D = brdf_density (m);
## wo = repmat ([sin(0.5) 0 cos(0.5)], 4, 1);
## [wi, p] = brdf_sample (D, wo, rand (4, 2));
## B = merl_standin ("red-plastic");
## [~, B.sampler] = brdf_density (B);      # fitted once, kept
## @end group
## @end example
## @seealso{brdf_sample, brdf_pdf, rt_render}
## @end deftypefn

function [D, model] = brdf_density (material)
  if (nargin != 1)
    print_usage ();
  endif
  if (isstruct (material) && isscalar (material) && isfield (material, "density_of"))
    D = material;
    model = D.model;
    return;
  endif
  kind = __lafortune_material_kind__ (material);
  switch (kind)
    case "merl"
      if (isfield (material, "sampler") && ! isempty (material.sampler))
        model = material.sampler;
      else
        S = merl_samples (material, "views", false, "max_samples", 20000);
        model = lafortune_fit (S, 2, "weight", "log");
      endif
    case {"lafortune", "model"}
      model = material;
    otherwise
      error ("lafortune:badMaterial",
             "brdf_density: MATERIAL must be an analytic model (see brdf_model) or a MERL material (fields data, valid), got %s",
             class (material));
  endswitch
  D = density_prep (model, "brdf_density");
  D.density_of = kind;
endfunction

%!test
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! [D, mm] = brdf_density (m);
%! assert (D.density_of, "lafortune");
%! assert (mm, m);
%! assert (D.wd, 0.2, 1e-15);
%! assert (brdf_density (D), D);

%!test
%! ## a MERL material: its sampler when it has one, else a fit made for sampling
%! B = merl_standin ("red-plastic");
%! B.sampler = struct ("rho_d", [0.2 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [9 9 9]);
%! [D, m] = brdf_density (B);
%! assert (m, B.sampler);
%! B = rmfield (B, "sampler");
%! [D, m] = brdf_density (B);
%! assert (size (m.e), [2 3]);
%! assert (all (isfinite (m.e(:))) && D.wd > 0);

%!error <Invalid call> brdf_density ()
%!error id=lafortune:badMaterial brdf_density (42)
%!error id=lafortune:badModel brdf_density (struct ("rho_d", [-1 0 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]))
%!error id=lafortune:badModel brdf_density (struct ("rho_d", [NaN 0 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]))
