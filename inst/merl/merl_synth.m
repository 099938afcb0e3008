## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{brdf} =} merl_synth (@var{fun})
## @deftypefnx {lafortune} {@var{brdf} =} merl_synth (@var{fun}, @var{name}, @var{value}, @dots{})
## Build a MERL-format material from any BRDF function.
##
## @var{fun} is a function handle @code{rgb = fun (wi, wo)} taking N x 3 unit
## directions (local frame, z = normal) and returning N x 3, or an analytic
## model struct of any type (a Lafortune model, or one of @code{brdf_model},
## e.g. GGX), evaluated by @code{material_eval}.  It is evaluated at every
## MERL bin's grid point
## (theta_h = (i/90)^2 pi/2, theta_d = j/90 pi/2, phi_d = k/180 pi).  Bins
## with a direction below the horizon hold 0.  Options:
##
## @table @code
## @item "name"
## material name (default @code{"synthetic"}).
## @item "noise"
## relative standard deviation of multiplicative Gaussian noise (default 0),
## like measurement noise; values stay >= 0.
## @item "missing"
## grazing angle in degrees (default: none): bins whose theta_i or theta_o
## exceeds it are marked missing (stored as -1) with probability
## @code{"missing_fraction"} (default 0.5), as in the real database.
## @item "seed"
## seed of the random generator for noise and missing samples (default 1).
## @end table
##
## The result has the fields of @code{merl_read}'s output; write it with
## @code{merl_write}.
##
## @example
## @group
## m = struct ("rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1], ...
##             "Cz", [1 1 1], "e", [50 50 50]);
## brdf = merl_synth (m, "name", "my-lobe", "noise", 0.05, "missing", 80);
## merl_write ([tempname() ".binary"], brdf);
## g = brdf_model ("ggx", "rho_d", [0.1 0.05 0.02], "ks", 1, ...
##                 "alpha", 0.2, "F0", 0.04);
## brdf = merl_synth (g, "name", "ggx");
## @end group
## @end example
## @seealso{merl_read, merl_write, merl_standin, brdf_model, material_eval}
## @end deftypefn
function brdf = merl_synth (fun, varargin)
  if (nargin < 1)
    print_usage ();
  endif
  if (isstruct (fun))
    ## any analytic model; material_eval evaluates a Lafortune one by
    ## lafortune_eval, as ever
    model = __lafortune_check_model__ (fun, "merl_synth");
    fun = @(wi, wo) material_eval (model, wi, wo);
  elseif (! is_function_handle (fun))
    error ("lafortune:badInput",
           "merl_synth: FUN must be a function handle rgb = fun (wi, wo) or an analytic model struct (see brdf_model)");
  endif
  opt = __lafortune_parse_opts__ (varargin, "merl_synth",
                    struct ("name", "synthetic", "noise", 0, "missing", [],
                            "missing_fraction", 0.5, "seed", 1));
  if (! ischar (opt.name))
    error ("lafortune:badOption", "merl_synth: NAME must be a string");
  endif
  if (! isscalar (opt.noise) || ! (opt.noise >= 0))
    error ("lafortune:badOption", "merl_synth: NOISE must be a scalar >= 0");
  endif
  [~, ~, n] = __lafortune_merl_consts__ ();
  [wi, wo] = __lafortune_merl_grid__ ();
  data = zeros (n, 3);
  above = find (wi(:,3) > 1e-12 & wo(:,3) > 1e-12);
  wi(above,:) ./= sqrt (sum (wi(above,:) .^ 2, 2));
  wo(above,:) ./= sqrt (sum (wo(above,:) .^ 2, 2));
  chunk = 262144;
  for s = 1:chunk:numel (above)
    k = above(s:min (s + chunk - 1, end));
    v = fun (wi(k,:), wo(k,:));
    if (! isequal (size (v), [numel(k) 3]) || ! isnumeric (v) || ! isreal (v))
      error ("lafortune:badInput",
             "merl_synth: FUN must return a real N x 3 array for N x 3 inputs, got %s",
             mat2str (size (v)));
    endif
    data(k,:) = double (v);
  endfor
  if (! all (isfinite (data(:))))
    error ("lafortune:badInput", "merl_synth: FUN returned NaN or Inf");
  endif
  valid = true (n, 1);
  if (opt.noise > 0 || ! isempty (opt.missing))
    rs = randn ("state");
    us = rand ("state");
    randn ("state", opt.seed);
    rand ("state", opt.seed);
    unwind_protect
      if (opt.noise > 0)
        data .*= max (1 + opt.noise * randn (n, 3), 0);
      endif
      if (! isempty (opt.missing))
        graz = min (wi(:,3), wo(:,3));   # cosine of the larger angle
        miss = graz < cosd (opt.missing) & rand (n, 1) < opt.missing_fraction;
        data(miss,:) = -1;
        valid(miss) = false;
      endif
    unwind_protect_cleanup
      randn ("state", rs);
      rand ("state", us);
    end_unwind_protect
  endif
  brdf = struct ("name", opt.name, "file", "", "data", data, "valid", valid);
endfunction

%!test
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! b = merl_synth (m, "name", "lambert");
%! assert (b.name, "lambert");
%! assert (size (b.data), [1458000 3]);
%! assert (all (b.valid));
%! t = (5:10:75)' * pi / 180;
%! wi = [sin(t) 0*t cos(t)];
%! assert (merl_eval (b, wi, [0 0 1]), repmat ([0.3 0.2 0.1] / pi, numel (t), 1), 1e-15);

%!test
%! ## noise and missing samples are reproducible and where they should be
%! f = @(wi, wo) ones (rows (wi), 3);
%! b1 = merl_synth (f, "noise", 0.2, "missing", 70, "seed", 3);
%! b2 = merl_synth (f, "noise", 0.2, "missing", 70, "seed", 3);
%! assert (isequal (b1.data, b2.data));
%! assert (any (! b1.valid));
%! assert (all (b1.data(! b1.valid,:)(:) == -1));
%! v = b1.data(b1.valid & b1.data(:,1) > 0, :);
%! assert (std (v(:)), 0.2, 0.01);
%! ## nothing missing at normal incidence
%! [~, ok] = merl_eval (b1, [0 0 1], [0 0 1]);
%! assert (ok);

%!test
%! ## every analytic type, through material_eval (a Lafortune model exactly
%! ## as lafortune_eval gives it), and read back by merl_eval
%! wi = [sind(30) 0 cosd(30); sind(45) 0 cosd(45); sind(50) 0 cosd(50)];
%! wo = [-sind(20) 0 cosd(20); -sind(45) 0 cosd(45); -sind(30) 0 cosd(30)];
%! for t = brdf_model ()
%!   d = brdf_model (t{1});
%!   if (strcmp (t{1}, "lafortune"))
%!     m = brdf_model ("lafortune", "rho_d", [0.3 0.2 0.1], "Cxy", [-1 -0.9 -1.1; 0.5 0.4 0.3], ...
%!                     "Cz", [0.9 1 0.8; 0.5 0.6 0.7], "e", [20 30 40; 3 4 5]);
%!   else
%!     m = brdf_model (t{1}, "rho_d", [0.3 0.2 0.1], "ks", [1 0.5 0.25; 0.1 0.2 0.3], ...
%!                     d.shape{1}, [0.3 0.4 0.5; 0.6 0.7 0.8] .^ (1 - 3 * (d.hi(2) > 100)));
%!     if (numel (d.shape) > 1)
%!       m.F0 = [0.04 0.5 1; 0.9 0.1 0];
%!     endif
%!   endif
%!   b = merl_synth (m, "name", t{1});
%!   assert (b.name, t{1});
%!   assert (all (b.valid) && all (b.data(:) >= 0));
%!   if (strcmp (t{1}, "lafortune"))
%!     r = merl_synth (@(wi, wo) lafortune_eval (m, wi, wo));
%!     assert (isequal (b.data, r.data));
%!   elseif (strcmp (t{1}, "ggx"))
%!     r = merl_synth (@(wi, wo) material_eval (m, wi, wo));
%!     assert (isequal (b.data, r.data));
%!   endif
%!   assert (merl_eval (b, wi, wo), material_eval (m, wi, wo), -0.05);
%! endfor

%!error <Invalid call> merl_synth ()
%!error id=lafortune:badInput merl_synth (42)
%!error id=lafortune:badInput merl_synth (@(wi, wo) ones (rows (wi), 2))
%!error id=lafortune:badOption merl_synth (@(wi, wo) wi, "noise", -1)
%!error id=lafortune:badOption merl_synth (@(wi, wo) wi, "colour", 1)
%!error id=lafortune:badModel merl_synth (struct ("type", "ggx", "rho_d", [0 0 0], "ks", 1, "alpha", 0.1, "F0", 0))
%!error id=lafortune:badModelType merl_synth (struct ("type", "phong", "rho_d", [0 0 0]))
