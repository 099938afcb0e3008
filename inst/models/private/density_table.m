## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} density_table (@var{brdf}, @var{nt}, @var{nu}, @var{np})
## A tabulated sampling density of a MERL material (private, for
## @code{brdf_density}): the data themselves, not a fit.  The views are
## cut into @var{nt} bins of theta_o (uniform in angle, the view of a bin
## its centre); for each, the half vector h (about the normal) is
## parametrized as MERL parametrizes theta_h, u = sqrt (theta_h/(pi/2)) in
## [0, 1], and by its azimuth from the view's, phi in [0, pi] (the data are
## isotropic, so -phi has the same density), on an @var{nu} x @var{np} grid.
## Each cell holds the density the data ask for at its centre, the mean of
## the channels of f (wi, wo) cos theta_i, wi = 2 (wo . h) h - wo, times
## the Jacobians from wi to h (4 wo . h) and from h to (u, phi) (pi u sin
## theta_h); a cell is drawn in proportion to it and then uniformly in (u,
## phi).  Fields: @code{sampler} ("table"), @code{nt}, @code{nu},
## @code{np}, @code{P} (nt x nu x np, each view's cells summing to 1),
## @code{cu} (nt x nu, the cumulative of each view's u marginal) and
## @code{cp} (nt nu x np, the cumulative of phi within each row, 0 for an
## empty row), @code{time} (seconds to make it).
## @end deftypefn
function T = density_table (brdf, nt = 32, nu = 64, np = 64)
  t0 = tic ();
  to = ((1:nt) - 0.5) / nt * pi / 2;
  [h, U, th] = __lafortune_half_grid__ (nu, np);   # u down the rows
  P = zeros (nt, nu, np);
  for b = 1:nt
    wo = [sin(to(b)), 0, cos(to(b))];
    c = h * wo.';
    wi = 2 * c .* h - wo;
    up = wi(:,3) > 0 & c > 0;
    t = zeros (rows (h), 1);
    if (any (up))
      f = merl_eval (brdf, wi(up,:), repmat (wo, sum (up), 1));
      t(up) = mean (max (f, 0), 2) .* wi(up,3) .* 4 .* c(up) .* pi .* U(up) .* sin (th(up));
    endif
    t(! isfinite (t)) = 0;
    if (sum (t) > 0)
      P(b,:,:) = reshape (t / sum (t), 1, nu, np);
    endif
  endfor
  cu = cumsum (sum (P, 3), 2);
  rowsum = reshape (permute (sum (P, 3), [2 1]), [], 1);
  Q = reshape (permute (P, [2 1 3]), nt * nu, np);   # row (b - 1) nu + i
  cp = cumsum (Q, 2) ./ max (rowsum, realmin);
  cp(rowsum <= 0,:) = 0;
  T = struct ("sampler", "table", "nt", nt, "nu", nu, "np", np, "P", P, "cu", cu, "cp", cp,
              "time", toc (t0));
endfunction
