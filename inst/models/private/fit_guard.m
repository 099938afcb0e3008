## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} fit_guard ()
## @deftypefnx {} {@var{ok} =} fit_guard (@var{p}, @var{G}, @var{ymax})
## @deftypefnx {} {@var{p} =} fit_guard ("repair", @var{p}, @var{ymax})
## The acceptance test of a fitted Lafortune channel (private).
##
## @code{G = fit_guard ()}: the pairs of the plane of incidence, theta_i in
## [0, 90] and theta_o in [-90, 90] degrees (negative on the mirror side)
## on a 0.5-degree grid; @code{G.x} = [a, c], @code{G.ti} and @code{G.to}
## the angles of each row (degrees).  A lobe's base Cxy a + Cz c is
## linear in (a, c) = (ux vx + uy vy, uz vz), and every pair of directions
## of the hemisphere has |a| + c <= 1, c >= 0, a triangle whose corners
## (a, c) = (0, 1), (1, 0) and (-1, 0) are in the plane: so G reaches
## each lobe's largest value anywhere on the hemisphere, whatever the
## table covers.
##
## @code{ok = fit_guard (p, G, ymax)}: false when the model @var{p} is not
## finite on G or exceeds 10 @var{ymax} there (a lobe that fits a few
## samples and explodes between them, or past the table's angles).  The sum
## of the lobes' peaks, max (Cz, |Cxy|, 0)^e each, bounds the model; only
## when that bound fails is the model evaluated on all of G.
##
## @code{p = fit_guard ("repair", p, ymax)}: @var{p} with each lobe whose
## peak exceeds its share of 10 @var{ymax} less rho_d / pi (the share: that
## bound over the number of lobes) scaled down to it (Cxy and Cz times one
## factor, made in log space); lobes within their share are kept as they
## are.  The result passes the guard.
## @end deftypefn
function out = fit_guard (p, G, ymax)
  if (nargin == 0)
    t = 0:0.5:90;
    [TI, TO] = ndgrid (t, [-fliplr(t(2:end)), t]);
    out = struct ("x", [sind(TI(:)) .* sind(TO(:)), cosd(TI(:)) .* cosd(TO(:))], "ti", TI(:),
                  "to", TO(:));
    return;
  endif
  if (ischar (p))
    out = repair (G, ymax);
    return;
  endif
  lim = 10 * max (ymax, realmin);
  bound = p(1) / pi + sum (exp (min (log_peaks (p), 700)));
  if (isfinite (bound) && bound <= lim)
    out = true;
    return;
  endif
  g = __lafortune_lafortune_core__ (p, G.x(:,1), G.x(:,2));
  out = all (isfinite (g)) && max (g) <= lim;
endfunction

## the log of each lobe's largest value on the hemisphere
function lp = log_peaks (p)
  L = reshape (p(2:end), 3, []);
  lp = __lafortune_log_peaks__ (L(1,:), L(2,:), L(3,:));
endfunction

function p = repair (p, ymax)
  nl = (numel (p) - 1) / 3;
  if (nl < 1 || ! all (isfinite (p)))
    return;
  endif
  cap = 10 * max (ymax, realmin) * (1 - 1e-9) - max (p(1), 0) / pi;
  if (! (cap > 0))
    p(2:end) = repmat ([0; 0; 1], nl, 1);
    return;
  endif
  lc = log (cap / nl);
  lp = log_peaks (p);
  for k = find (lp > lc)
    e = p(3*k+1);
    if (e > 0)
      p(3*k-1:3*k) *= exp ((lc - lp(k)) / e);
    else                                 # a step: its height is 1
      p(3*k-1:3*k) = 0;
    endif
  endfor
endfunction
