## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{peak} =} __lafortune_check_bounded__ (@var{model})
## @deftypefnx {} {} __lafortune_check_bounded__ (@var{model}, @var{fname})
## A bound of an analytic @var{model} on the hemisphere, per channel
## (internal), or, with @var{fname}, the error
## @code{lafortune:unboundedModel} when it is not finite or above 1e30.
##
## For a Lafortune model: rho_d / pi plus each lobe's largest value, max
## (Cz, |Cxy|, 0)^e (made in log space), which the lobe reaches at normal
## light and view (Cz) or grazing ones (|Cxy|, on the side of the light or
## the mirror side); the largest value itself when the lobes peak
## together.  For the other types the model is evaluated (material_eval) on the
## plane of incidence on a 1-degree grid, theta_i and theta_o in [0, 90].
## The message names the channel, the lobe and the directions.  A model
## that fails here is infinite somewhere in a scene: the readers and
## writers of models (brdf_import, brdf_export) and the renderers
## (rt_render, pov_write_scene) reject it rather than render Inf.
##
## @example
## M = struct ("rho_d", [0.1 0.1 0.1], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [10 10 10]);
## __lafortune_check_bounded__ (M)        # 0.1 / pi + 1
## @end example
## @end deftypefn

function peak = __lafortune_check_bounded__ (model, fname)
  LIMIT = 1e30;
  if (strcmp (__lafortune_material_kind__ (model), "lafortune"))
    [lp, k, where] = lafortune_peaks (model);
  else
    [lp, k, where] = grid_peaks (model);
  endif
  peak = exp (min (lp, 709.7));
  peak(lp > 709.7) = Inf;
  if (nargin < 2)
    return;
  endif
  bad = find (! (lp <= log (LIMIT)), 1);
  if (! isempty (bad))
    error ("lafortune:unboundedModel",
           "%s: the model is unbounded: channel %d%s reaches %s at %s; expected a value below %g everywhere on the hemisphere",
           fname, bad, lobe_text (k(bad)), value_text (lp(bad)), where{bad}, LIMIT);
  endif
endfunction

## the log of each channel's peak, the lobe that makes most of it and where
function [lp, kbig, where] = lafortune_peaks (M)
  nc = numel (M.rho_d);
  lp = zeros (1, nc);
  kbig = zeros (1, nc);
  where = cell (1, nc);
  for c = 1:nc
    cxy = M.Cxy(:,c); cz = M.Cz(:,c);
    terms = [log(max (M.rho_d(c), 0) / pi); __lafortune_log_peaks__(cxy, cz, M.e(:,c))];
    if (! isfinite (M.rho_d(c)))
      terms(1) = Inf;
    endif
    m = max (terms);
    if (isinf (m))
      lp(c) = m;
    else
      lp(c) = m + log (sum (exp (terms - m)));
    endif
    [~, i] = max (terms);
    kbig(c) = i - 1;
    where{c} = "normal light and view (theta_i = theta_o = 0 degrees)";
    if (i > 1 && abs (cxy(i-1)) > cz(i-1))
      side = "the side of the light";
      if (cxy(i-1) < 0)
        side = "the mirror side";
      endif
      where{c} = sprintf ("grazing light and view on %s (theta_i = theta_o = 90 degrees)", side);
    endif
  endfor
endfunction

## any other type: the largest value on a 1-degree grid of the plane
function [lp, kbig, where] = grid_peaks (M)
  t = 0:90;
  to = [-fliplr(t(2:end)), t];
  [TI, TO] = ndgrid (t, to);
  wi = [sind(TI(:)), zeros(numel (TI), 1), cosd(TI(:))];
  wo = [sind(TO(:)), zeros(numel (TO), 1), cosd(TO(:))];
  f = material_eval (M, wi, wo);
  f(! isfinite (f)) = Inf;
  [m, i] = max (f, [], 1);
  lp = log (max (m, realmin));
  kbig = zeros (size (lp));
  where = arrayfun (@(j) sprintf ("theta_i = %g, theta_o = %g degrees (%s)", TI(j), abs (TO(j)),
                                  side_of (TO(j))), i, "uniformoutput", false);
endfunction

function s = side_of (to)
  s = "on the side of the light";
  if (to < 0)
    s = "on the mirror side";
  endif
endfunction

function s = lobe_text (k)
  s = "";
  if (k > 0)
    s = sprintf (", lobe %d,", k);
  endif
endfunction

function s = value_text (lp)
  if (isinf (lp) || isnan (lp))
    s = "a value that is not finite";
  else
    s = sprintf ("about 1e%d", round (lp / log (10)));
  endif
endfunction

%!test
%! M = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.5 0.8], "Cz", [1 0.9 0.7], "e", [10 2 3]);
%! assert (__lafortune_check_bounded__ (M), [0.1 0.2 0.3] / pi + [1 0.9^2 0.8^3], 1e-12);
%!test
%! ## a bound of the values on a fine grid of the hemisphere, reached by one lobe
%! M = struct ("rho_d", [0 0 0], "Cxy", [-1.2 0.3; -0.4 -0.9; 0.5 0.2]', "Cz", [0.9 1.1; 1 0.6; 0.3 0.1]',
%!             "e", [8 3; 20 5; 2 1]');
%! t = linspace (0, 90, 91) * pi / 180;  p = linspace (0, 2 * pi, 73);
%! [a, b, c] = ndgrid (t, t, p);
%! wi = [sin(a(:)), zeros(numel (a), 1), cos(a(:))];
%! wo = [sin(b(:)) .* cos(c(:)), sin(b(:)) .* sin(c(:)), cos(b(:))];
%! g = max (lafortune_eval (M, wi, wo), [], 1);
%! pk = __lafortune_check_bounded__ (M);
%! assert (all (g <= pk * (1 + 1e-12)));
%! L = M;  L.Cxy = M.Cxy(1,:);  L.Cz = M.Cz(1,:);  L.e = M.e(1,:);
%! assert (max (lafortune_eval (L, wi, wo)), __lafortune_check_bounded__ (L), 1e-9);
%!test
%! M = brdf_model ("ggx", "rho_d", [0.1 0.1 0.1], "ks", [0.5 0.5 0.5], "alpha", [0.2 0.2 0.2],
%!                 "F0", [0.04 0.04 0.04]);
%! pk = __lafortune_check_bounded__ (M);
%! assert (all (isfinite (pk)) && all (pk > 0.1 / pi));
%! __lafortune_check_bounded__ (M, "test");
%!error <test: the model is unbounded: channel 1, lobe 1, reaches about 1e130 at grazing light and view on the mirror side> __lafortune_check_bounded__ (struct ("rho_d", [0 0 0], "Cxy", [-1.5 0 0], "Cz", [0.9 0 0], "e", [738 1 1]), "test")
%!error <channel 2 reaches a value that is not finite> __lafortune_check_bounded__ (struct ("rho_d", [0 Inf 0], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]), "test")
%!error <lobe 2, reaches about 1e60 at normal light and view> __lafortune_check_bounded__ (struct ("rho_d", [0 0 0], "Cxy", [-1 -1; 0 0; 0 0]', "Cz", [1 10; 0 0; 0 0]', "e", [5 60; 1 1; 1 1]'), "t")
