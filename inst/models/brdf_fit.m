## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} brdf_fit (@var{S}, @var{type}, @var{nlobes})
## @deftypefnx {lafortune} {@var{model} =} brdf_fit (@var{S}, @var{type}, @var{nlobes}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{model}, @var{info}, @var{models}] =} brdf_fit (@dots{})
## Fit an analytic model of @var{type} with @var{nlobes} lobes (1 to 8)
## over a Lambertian term to a table of BRDF samples.
##
## @var{type} is one of @code{brdf_model ()}.  @code{"lafortune"} is
## @code{lafortune_fit (S, nlobes, @dots{})}, with all its options (the
## paper's fit).  The physically based types (@code{"blinnphong"},
## @code{"ward"}, @code{"cooktorrance"}, @code{"ggx"},
## @code{"ashikhminshirley"}) are fitted by optim's @code{leasqr} with the
## analytic Jacobian and their type's bounds (ks >= 0, rho_d >= 0,
## roughness and exponents > 0 within the ranges @code{brdf_model (type)}
## gives in @code{lo} and @code{hi}, F0 in [0, 1]; roughness and exponents
## are moved by their logarithm).  @var{S} is a table as @code{lafortune_fit} takes it
## (@code{merl_plane}, @code{merl_samples}, @code{merl_scene}; optional
## @code{weight}, a scene table's prior), and the fit keeps what
## @code{lafortune_fit} does: the same metrics and defaults, samples merged
## by what the model sees of a pair of directions (for these types (cos
## theta_i, cos theta_o, wi.wo): exact, or cells of a grid for a large
## table, @code{"reduce"}), the data divided by their largest
## magnitude (fitting c*y gives c times the fit of y), lobes grown one at a
## time from the fit with one lobe fewer (so the fit's objective, on the
## samples or cells it runs on, never rises with more lobes), a guard (a result that is not finite or exceeds 10 times
## the data's maximum on the data is rejected; a Lafortune model is held
## to that bound on the whole hemisphere, see lafortune_fit; the
## physically based types are finite everywhere by their parameters'
## bounds), and the trace of the error against run time.
##
## Options:
## @table @code
## @item "weight"
## the metric, as @code{lafortune_fit}'s (default @code{"plain"};
## @code{"relative"} for a scene table; for a hemisphere table of
## @code{merl_samples} with its training views the general fit,
## @code{"select"}: each candidate weighting fitted, the one that looks
## best in the views kept per lobe count, as @code{lafortune_fit} does).
## @item "color"
## @code{"separate"} (default: each channel its own model) or
## @code{"shared"} (one shape per lobe for R, G and B, an amplitude per
## channel: the highlight keeps its colour; one leasqr run over the
## channels).
## @item "tries"
## leasqr runs per added lobe, from the best candidate shapes of the type's
## grid (default 2; 4 for a scene table).
## @item "energy"
## false (default) or true: a fit that reflects more light than it receives
## (@code{brdf_albedo} > 1 at some incidence) is refitted with Octave's
## @code{sqp} under the constraint albedo <= 1.
## @item "reduce"
## @code{"auto"} (default: samples equal in (cos theta_i, cos theta_o,
## wi.wo) merged exactly up to 20000 samples; a larger table, such as the
## whole hemisphere or a scene table's prior, on the cells of a 64 x 64 x
## 64 grid over (sqrt (theta_h), theta_d, |cos theta_i - cos theta_o|), at
## the weighted mean of their samples), @code{"exact"}, or n: an n x n x n
## grid.
## @item "max_iter", "tol", "channels"
## as @code{lafortune_fit}'s.
## @end table
##
## @var{info} has @code{lafortune_fit}'s fields (errors per channel, on all
## samples of @var{S}: @code{rmse}, @code{rel_rmse}, @code{log_rmse},
## @code{cos_rmse}, @code{error}; @code{history}, @code{trace},
## @code{time}, @code{iterations}, @code{rejected}, @code{converged},
## @code{lobe_time}, @code{n}, @code{groups}, @code{reduce}) and
## @code{type}, @code{albedo} (1 x 3, the largest albedo over the incidence
## angles 0, 5, @dots{}, 85 and 89 degrees, where @code{"energy"} also
## constrains it), @code{albedo_lobes} (nlobes x 3: the same for the fit
## with each lobe count, @var{models}), @code{energy} (1 x 3, albedo <= 1) and
## @code{enforced} (whether the constraint was applied).  @var{models}
## holds the fits with 1 .. @var{nlobes} lobes.
##
## Errors: @code{lafortune:badModelType}, @code{lafortune:badLobes},
## @code{lafortune:badOption}, @code{lafortune:badSamples}.
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## S = merl_plane (brdf);
## [m, info] = brdf_fit (S, "ggx", 2);
## info.rmse, info.albedo
## m1 = brdf_fit (S, "cooktorrance", 1, "color", "shared");
## ml = brdf_fit (S, "lafortune", 3);        # the paper's fit, lafortune_fit
## me = brdf_fit (S, "blinnphong", 1, "energy", true);
## mg = brdf_fit (merl_samples (brdf), "ggx", 2);   # the general fit
## @end group
## @end example
## @seealso{brdf_model, brdf_albedo, lafortune_fit, material_eval}
## @end deftypefn

function [model, info, models] = brdf_fit (S, type, nlobes, varargin)
  if (nargin < 3)
    print_usage ();
  endif
  fname = "brdf_fit";
  if (! ischar (type) || ! any (strcmp (type, __lafortune_model_def__ ())))
    error ("lafortune:badModelType", "%s: TYPE must be one of %s, got '%s'", fname,
           strjoin (__lafortune_model_def__ (), ", "), __lafortune_arg_str__ (type));
  endif
  if (strcmp (type, "lafortune"))
    [model, info, models] = lafortune_fit (S, nlobes, varargin{:});
    info.type = "lafortune";
    return;
  endif
  if (! (isnumeric (nlobes) && isscalar (nlobes) && nlobes == fix (nlobes)
         && nlobes >= 1 && nlobes <= 8))
    error ("lafortune:badLobes", "%s: NLOBES must be an integer from 1 to 8, got %s",
           fname, num2str (nlobes));
  endif
  def = __lafortune_model_def__ (type);
  opt = __lafortune_parse_opts__ (varargin, fname,
                    struct ("weight", [], "color", [], "tries", [], "energy", false,
                            "max_iter", 100, "tol", 1e-7, "channels", 1:3, "reduce", "auto"));
  scene = isstruct (S) && isscalar (S) && isfield (S, "kind") && ischar (S.kind) && strcmp (S.kind, "scene");
  if (isempty (opt.tries))
    opt.tries = merge (scene, 4, 2);
  endif
  opt = fit_defaults (opt, S);
  if (strcmp (opt.weight, "select"))    # the general fit: chosen by the table's views
    V = select_views (S, fname);
    S = rmfield (S, "views");
    [model, info, models] = fit_select (V, nlobes,
                                        @(w) brdf_fit (S, type, nlobes, varargin{:}, "weight", w));
    info.type = type;
    return;
  endif
  opt = check_opts (opt, fname);
  [S, wt, n0] = fit_table (S, opt.weight, fname);
  pkg_load_optim ();
  opt.bounds = true;                    # (leasqr's options: fit_lm)
  opt.jacobian = "analytic";
  opt.start = [];                       # always a growing fit
  opt.init = "grow";
  [models, info] = fit_driver (S, wt, n0, def, nlobes, opt, fname);
  [model, models] = fit_table (S, models{nlobes}, models);   # the table's name
endfunction

function opt = check_opts (opt, fname)
  if (! ischar (opt.weight) || ! any (strcmp (opt.weight, metric_spec ())))
    error ("lafortune:badOption", "%s: WEIGHT must be one of %s", fname,
           strjoin (metric_spec (), ", "));
  endif
  if (! ischar (opt.color) || ! any (strcmpi (opt.color, {"separate", "shared"})))
    error ("lafortune:badOption", "%s: COLOR must be \"separate\" or \"shared\"", fname);
  endif
  opt.color = lower (opt.color);
  if (! isscalar (opt.tries) || ! (opt.tries >= 1))
    error ("lafortune:badOption", "%s: TRIES must be a positive integer", fname);
  endif
  if (! (isscalar (opt.energy) && (islogical (opt.energy) || isnumeric (opt.energy))))
    error ("lafortune:badOption", "%s: ENERGY must be true or false", fname);
  endif
  opt.energy = logical (opt.energy);
  if (! isscalar (opt.max_iter) || ! (opt.max_iter >= 1))
    error ("lafortune:badOption", "%s: MAX_ITER must be a positive integer", fname);
  endif
  if (! isscalar (opt.tol) || ! (opt.tol >= 0))
    error ("lafortune:badOption", "%s: TOL must be a scalar >= 0", fname);
  endif
  if (! isnumeric (opt.channels) || isempty (opt.channels) || any (! ismember (opt.channels, 1:3)))
    error ("lafortune:badOption", "%s: CHANNELS must be a subset of 1:3", fname);
  endif
  opt.channels = unique (opt.channels(:)');
  if (! ((ischar (opt.reduce) && any (strcmp (opt.reduce, {"auto", "exact"})))
         || (isnumeric (opt.reduce) && isscalar (opt.reduce) && opt.reduce >= 1
             && opt.reduce == fix (opt.reduce))))
    error ("lafortune:badOption",
           "%s: REDUCE must be \"auto\", \"exact\" or a positive integer (grid cells per axis)", fname);
  endif
endfunction

%!demo
%! ## the paper's in-plane table of the red plastic stand-in, every model
%! S = merl_plane (merl_standin ("red-plastic"));
%! for t = brdf_model ()
%!   [m, info] = brdf_fit (S, t{1}, 2);
%!   printf ("%-18s rmse (R G B) %s\n", t{1}, mat2str (info.rmse, 3));
%! endfor

%!test
%! ## a GGX material's own in-plane data: recovered, scale invariant
%! m = brdf_model ("ggx", "rho_d", [0.2 0.1 0.05], "ks", [0.5 0.4 0.3], "alpha", 0.2, "F0", 0.04);
%! [ti, to] = ndgrid ((0:5:80) * pi / 180, (-80:1:80) * pi / 180);
%! S = struct ("wi", [sin(ti(:)) zeros(numel (ti), 1) cos(ti(:))], ...
%!             "wo", [-sin(to(:)) zeros(numel (ti), 1) cos(to(:))]);
%! S.rgb = material_eval (m, S.wi, S.wo);
%! [f, info, ms] = brdf_fit (S, "ggx", 1);
%! assert (f.alpha, m.alpha, 1e-6);
%! assert (f.F0, m.F0, 1e-6);
%! assert (f.ks, m.ks, 1e-6);
%! assert (info.rmse < 1e-8);
%! assert (info.energy);
%! S.rgb *= 1e3;
%! g = brdf_fit (S, "ggx", 1);
%! assert (g.ks / 1e3, f.ks, 1e-9);
%! assert (g.alpha, f.alpha, 1e-9);

%!test
%! ## the general fit of another type: a hemisphere table with training views,
%! ## each candidate weighting fitted, the best in the views kept per lobe count
%! m = brdf_model ("ggx", "rho_d", [0.2 0.1 0.05], "ks", [0.5 0.4 0.3], "alpha", 0.2, "F0", 0.04);
%! S = merl_samples (merl_synth (m), "max_samples", 3000);
%! [f, info, ms] = brdf_fit (S, "ggx", 2);
%! assert (info.type, "ggx");
%! assert (any (strcmp (info.weight, {"log", "cuberoot"})));
%! assert (size (info.selection.flip), [2 2]);
%! assert (numel (ms), 2);
%! assert (rows (ms{2}.ks), 2);
%! assert (isequal (ms{2}, f));
%! ## GGX data: one GGX lobe already looks right in the views
%! assert (min (info.selection.flip(:,1)) < 0.05, mat2str (info.selection.flip, 3));
%! assert (f.alpha(1,:), [0.2 0.2 0.2], 0.02);
%!error <needs a table with training views> brdf_fit (merl_samples (merl_synth (struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [10 10 10])), "max_samples", 100, "views", false), "ggx", 1, "weight", "select")

%!error <Invalid call> brdf_fit (1, "ggx")
%!error id=lafortune:badModelType brdf_fit (struct (), "phong", 1)
%!error id=lafortune:badLobes brdf_fit (struct (), "ggx", 0)
%!error id=lafortune:badOption brdf_fit (struct (), "ggx", 1, "colour", "shared")
%!error id=lafortune:badOption brdf_fit (struct (), "ggx", 1, "energy", "yes")
%!error id=lafortune:badSamples brdf_fit (struct ("wi", [0 0 1]), "ggx", 1)
