## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{D} =} brdf_density (@var{material})
## @deftypefnx {lafortune} {@var{D} =} brdf_density (@var{material}, @var{method})
## @deftypefnx {lafortune} {[@var{D}, @var{model}] =} brdf_density (@dots{})
## The density by which directions toward the light are drawn for a
## material: what @code{brdf_sample} draws from and @code{brdf_pdf}
## evaluates, and what @code{rt_render} combines with the light's own
## samples (multiple importance sampling).
##
## @var{material} is an analytic model of any type (@code{brdf_model}):
## its own lobes are the density.  For a MERL material (@code{merl_read})
## the density is the one in its field @code{sampler} when it has one, else
## by @var{method}: @qcode{"table"} (the default) tabulates the data
## themselves: per bin of the view's polar angle (32), a grid of half
## vectors (64 steps of sqrt (theta_h), as MERL's own bins, by 64 of their
## azimuth from the view's) holds f cos theta_i, each cell drawn in
## proportion to it, beside a tenth of cosine-weighted samples that reach
## every direction; @qcode{"fit"} fits 2 Lafortune lobes with the log
## weighting to 20000 samples of the hemisphere (@code{merl_samples}
## without views) and samples their lobes.  Keep @var{model} (the second
## output: the table or the fit) in @code{material.sampler} to make it
## once per material; a table is itself a valid @var{material} here.  A
## table also keeps @code{m2}, its second moment against the cosine, from
## which @code{rt_render} takes the share of BRDF samples.
##
## @var{D} is a struct for @code{brdf_sample} and @code{brdf_pdf}: the
## density's parts that do not depend on the view, prepared once; its field
## @code{model} is the model or table it follows.
##
## Errors: @code{lafortune:badMaterial} (neither a model nor MERL data),
## @code{lafortune:badOption} (@var{method} neither "table" nor "fit"),
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
## [~, B.sampler] = brdf_density (B);      # tabulated once, kept
## @end group
## @end example
## @seealso{brdf_sample, brdf_pdf, rt_render}
## @end deftypefn

function [D, model] = brdf_density (material, method = "table")
  if (nargin < 1 || nargin > 2)
    print_usage ();
  endif
  if (! (ischar (method) && any (strcmp (method, {"fit", "table"}))))
    error ("lafortune:badOption", "brdf_density: METHOD must be \"fit\" or \"table\", got %s",
           __lafortune_arg_str__ (method));
  endif
  if (isstruct (material) && isscalar (material) && isfield (material, "density_of"))
    D = material;
    model = D.model;
    return;
  endif
  kind = merge (is_table (material), "table", __lafortune_material_kind__ (material));
  switch (kind)
    case "merl"
      if (isfield (material, "sampler") && ! isempty (material.sampler))
        model = material.sampler;
      elseif (strcmp (method, "table"))
        model = density_table (material);
      else
        S = merl_samples (material, "views", false, "max_samples", 20000);
        model = lafortune_fit (S, 2, "weight", "log");
      endif
    case {"table", "lafortune", "model"}
      model = material;
    otherwise
      error ("lafortune:badMaterial",
             "brdf_density: MATERIAL must be an analytic model (see brdf_model) or a MERL material (fields data, valid), got %s",
             class (material));
  endswitch
  D = density_prep (model, "brdf_density", is_table (model));
  D.density_of = kind;
  if (D.table && ! isfield (model, "m2"))   # how sharp it is, kept with the table
    model.m2 = __lafortune_density_m2__ (D);
    D.model = model;
  endif
endfunction

## a tabulated density of MERL data (density_table)
function t = is_table (m)
  t = isstruct (m) && isscalar (m) && isfield (m, "sampler") && ischar (m.sampler) ...
      && strcmp (m.sampler, "table");
endfunction

%!test
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! [D, mm] = brdf_density (m);
%! assert (D.density_of, "lafortune");
%! assert (mm, m);
%! assert (D.wd, 0.2, 1e-15);
%! assert (brdf_density (D), D);

%!test
%! ## a MERL material: its sampler when it has one, even with METHOD "table"
%! B = merl_standin ("red-plastic");
%! B.sampler = struct ("rho_d", [0.2 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [9 9 9]);
%! [D, m] = brdf_density (B);
%! assert (m, B.sampler);
%! [D, m] = brdf_density (B, "table");
%! assert (m, B.sampler);

%!test
%! ## a MERL material's default density is a table of its data, which
%! ## integrates to 1 over the directions (midpoint quadrature in the
%! ## table's own parameters: half vectors by sqrt (theta_h) and azimuth)
%! B = merl_standin ("green-metallic-paint");
%! [D, T] = brdf_density (B);
%! assert (T.sampler, "table");
%! assert (D.density_of, "merl");
%! assert (size (T.P), [32 64 64]);
%! assert (brdf_density (T).model, T);
%! n = 1200; m = 600;
%! [PH, U] = meshgrid (((1:m) - 0.5) / m * 2 * pi - pi, ((1:n) - 0.5) / n);
%! th = pi / 2 * U(:) .^ 2;
%! h = [sin(th) .* cos(PH(:)), sin(th) .* sin(PH(:)), cos(th)];
%! for t = [0.01 0.7 1.4]
%!   wo = [sin(t) 0 cos(t)];
%!   c = h * wo.';
%!   wi = 2 * c .* h - wo;
%!   p = brdf_pdf (D, repmat (wo, rows (wi), 1), wi);
%!   I = sum (p .* 4 .* max (c, 0) .* pi .* U(:) .* sin (th)) / (n * m) * 2 * pi;
%!   ## the cosine part below the table's cells' horizon is all that is missing
%!   assert (abs (I - 1) < 2e-3, sprintf ("at %g: %g", t, I));
%! endfor

%!test
%! ## draws of a table: unbiased estimates of the albedo (against quadrature
%! ## of the data), and bounded weights f cos / p on a sharp material
%! B = merl_standin ("green-metallic-paint");
%! D = brdf_density (B);
%! state = rand ("state");
%! rand ("state", 3);
%! wo = [sin(0.6) 0 cos(0.6)];
%! N = 100000;
%! [wi, p] = brdf_sample (D, repmat (wo, N, 1), rand (N, 2));
%! g = mean (merl_eval (B, wi, repmat (wo, N, 1)), 2) .* max (wi(:,3), 0) ./ p;
%! g(p == 0) = 0;
%! n = 1500; m = 600;
%! [PH, U] = meshgrid (((1:m) - 0.5) / m * 2 * pi - pi, ((1:n) - 0.5) / n);
%! th = pi / 2 * U(:) .^ 2;
%! h = [sin(th) .* cos(PH(:)), sin(th) .* sin(PH(:)), cos(th)];
%! c = h * wo.';
%! w = 2 * c .* h - wo;
%! A = sum (mean (merl_eval (B, w, repmat (wo, rows (w), 1)), 2) .* max (w(:,3), 0)
%!          .* 4 .* max (c, 0) .* pi .* U(:) .* sin (th)) / (n * m) * 2 * pi;
%! assert (abs (mean (g) - A) < 4 * std (g) / sqrt (N) + 1e-3 * A);
%! assert (max (g) < 20 * A);
%! rand ("state", state);

%!test
%! ## bad data: NaN, Inf and negative bins give a finite table whose views'
%! ## cells sum to 1; a black material's table is empty, and its draws are
%! ## the cosine's, with the cosine's density
%! B = merl_standin ("red-plastic");
%! B.data(1:97:end,:) = NaN;
%! B.data(5:89:end,:) = Inf;
%! B.data(7:83:end,:) = -1;
%! [~, T] = brdf_density (B);
%! assert (all (isfinite (T.P(:)) & T.P(:) >= 0) && isfinite (T.m2));
%! assert (sum (reshape (T.P, T.nt, []), 2), ones (T.nt, 1), 1e-12);
%! B.data(:) = 0;
%! [D, T] = brdf_density (B);
%! assert (all (T.P(:) == 0));
%! wo = repmat ([sin(0.4) 0 cos(0.4)], 200, 1);
%! [wi, p] = brdf_sample (D, wo, rand (200, 2));
%! assert (p, wi(:,3) / pi, 1e-14);

%!test
%! ## "fit": 2 Lafortune lobes made for sampling
%! [D, m] = brdf_density (merl_standin ("red-plastic"), "fit");
%! assert (size (m.e), [2 3]);

%!error <Invalid call> brdf_density ()
%!error id=lafortune:badOption brdf_density (merl_standin ("red-plastic"), "bogus")
%!error id=lafortune:badMaterial brdf_density (42)
%!error id=lafortune:badModel brdf_density (struct ("rho_d", [-1 0 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]))
%!error id=lafortune:badModel brdf_density (struct ("rho_d", [NaN 0 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]))
