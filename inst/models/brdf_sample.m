## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {[@var{wi}, @var{p}] =} brdf_sample (@var{D}, @var{wo}, @var{u})
## @deftypefnx {lafortune} {[@var{wi}, @var{p}] =} brdf_sample (@var{D}, @var{wo}, @var{u}, @var{own})
## Draw directions toward the light in proportion to a material's
## sampling density, with the density of each: importance sampling of the
## BRDF (a renderer's Sample_f; @code{brdf_pdf} is its PDF).
##
## @var{D} is a density of @code{brdf_density}, or a model of any type;
## @var{wo} N x 3 unit viewing directions in the local frame (z = normal);
## @var{u} N x 2 uniforms in [0, 1).  The density is a mixture: the
## cosine-weighted hemisphere with weight rho_d (the mean over the
## channels), and for each lobe of each channel its own sampling, chosen in
## proportion to the lobe's weight: a Lafortune lobe, cos^e of the angle to
## its axis a = (Cxy vx, Cxy vy, Cz vz)/|(...)| (weight |a|^e 2 pi/(e+1)
## times the axis's cosine, at least 0.05, in log space); a lobe of a
## physically based type, the GGX distribution of half vectors (GGX's own
## sampling, as pbrt-v3's; for the other types with the roughness of the
## type's angular width), weight ks times its albedo at normal incidence.
## The first uniform chooses the component and is reused within it, so
## stratified uniforms stay stratified.  With @var{own} (N x 1 indices into
## the rows of @var{wo}) sample i is drawn for the view @var{wo}(@var{own}(i),:):
## many samples of one view share its mixture, made once.
##
## @var{wi} (N x 3, unit; below the horizon where a lobe reaches there:
## the BRDF is 0 there and such a sample adds nothing) and @var{p} (N x 1,
## @code{brdf_pdf (D, wo, wi)}, the whole mixture's density).
##
## Errors: those of @code{brdf_density} and @code{brdf_pdf}, and
## @code{lafortune:badOption} for @var{u} that is not N x 2 in [0, 1].
##
## @example
## @group
## m = brdf_model ("ggx", "rho_d", [0.1 0.1 0.1], "ks", 1, "alpha", 0.1, "F0", 0.9);
## wo = repmat ([sin(0.3) 0 cos(0.3)], 1000, 1);
## [wi, p] = brdf_sample (m, wo, rand (1000, 2));
## mean (wi)                 # near the mirror direction [-0.30 0 0.96]
## f = material_eval (m, wi, wo);
## mean (f(:,1) .* max (wi(:,3), 0) ./ p)   # an estimate of the albedo at 0.3
## @end group
## @end example
## @seealso{brdf_pdf, brdf_density, rt_render}
## @end deftypefn

function [wi, p] = brdf_sample (D, wo, u, own = [])
  if (nargin < 3 || nargin > 4)
    print_usage ();
  endif
  D = brdf_density (D);
  if (! (isnumeric (u) && isreal (u) && columns (u) == 2 && all (u(:) >= 0 & u(:) <= 1)))
    error ("lafortune:badOption", "brdf_sample: U must be N x 2 uniforms in [0, 1], got %s",
           mat2str (size (u)));
  endif
  own = __lafortune_check_views__ (wo, zeros (rows (u), 3), own, "brdf_sample");
  u = double (u);
  M = density_mix (D, wo);             # once per view
  W = M.W(own,:);
  C = cumsum (W, 2);
  j = min (sum (C < u(:,1), 2) + 1, columns (C));
  k = sub2ind (size (C), (1:rows (C)).', j);
  uu = min (max ((u(:,1) - (C(k) - W(k))) ./ max (W(k), realmin), 0), 1 - eps);
  wi = zeros (rows (u), 3);
  for c = unique (j).'
    r = find (j == c);
    wi(r,:) = density_draw (M, wo(own(r),:), c, uu(r), min (u(r,2), 1 - eps), own(r));
  endfor
  if (nargout > 1)
    p = brdf_pdf (D, wo, wi, own);
  endif
endfunction

%!function [m, names] = density_cases ()
%!  names = {"lafortune", "ggx", "cooktorrance", "blinnphong", "ward", "ashikhminshirley", "table"};
%!  m = cell (size (names));
%!  m{1} = struct ("rho_d", [0.2 0.1 0.1], "Cxy", [-1 -0.9 -1; 0.5 0.4 0.5], "Cz", [0.9 1 1; 0.5 0.5 0.5],
%!                 "e", [40 20 30; 3 3 4]);
%!  m{2} = brdf_model ("ggx", "rho_d", [0.2 0.1 0.1], "ks", 1, "alpha", 0.2, "F0", 0.5);
%!  m{3} = brdf_model ("cooktorrance", "rho_d", [0.1 0.1 0.1], "ks", 1, "m", 0.3, "F0", 0.5);
%!  m{4} = brdf_model ("blinnphong", "rho_d", [0.1 0.1 0.1], "ks", 1, "n", 40);
%!  m{5} = brdf_model ("ward", "rho_d", [0.1 0.1 0.1], "ks", 1, "alpha", 0.25);
%!  m{6} = brdf_model ("ashikhminshirley", "rho_d", [0.1 0.1 0.1], "ks", 1, "n", 30, "F0", 0.5);
%!  [~, m{7}] = brdf_density (merl_standin ("green-metallic-paint"));   # a MERL table
%!endfunction

%!test
%! ## every type's density integrates to 1 over the sphere (midpoint
%! ## quadrature, equal-area cells in z and phi), at three views (grazing
%! ## views put the GGX density's integrable 1/|wo.h| where cells undercount
%! ## it, and a table's cells near the mirror direction its integrable 1/u^3;
%! ## brdf_density's test integrates the table in its own parameters to 2e-3)
%! [ms, names] = density_cases ();
%! tol = [2e-3 * ones(1, 6), 5e-3];
%! nz = 700; np = 700;
%! [Z, PH] = ndgrid (-1 + (2 * (1:nz) - 1) / nz, (2 * (1:np) - 1) / np * pi);
%! s = sqrt (1 - Z(:) .^ 2);
%! wi = [s .* cos(PH(:)), s .* sin(PH(:)), Z(:)];
%! dA = (2 / nz) * (2 * pi / np);
%! for i = 1:numel (ms)
%!   for t = [0 0.5 1.0]
%!     wo = repmat ([sin(t) 0 cos(t)], rows (wi), 1);
%!     I = sum (brdf_pdf (ms{i}, wo, wi)) * dA;
%!     assert (abs (I - 1) < tol(i), sprintf ("%s at %g: %g", names{i}, t, I));
%!   endfor
%! endfor

%!test
%! ## draws follow the density: chi-square over equal-area bins (seeded)
%! [ms, names] = density_cases ();
%! state = rand ("state");
%! rand ("state", 7);
%! nb = 24; n = 40000; q = 20;
%! [Z, PH] = ndgrid (-1 + (2 * (1:nb*q) - 1) / (nb*q), (2 * (1:nb*q) - 1) / (nb*q) * pi);
%! s = sqrt (1 - Z(:) .^ 2);
%! g = [s .* cos(PH(:)), s .* sin(PH(:)), Z(:)];
%! bz = floor ((Z(:) + 1) / 2 * nb); bp = floor (PH(:) / (2 * pi) * nb);
%! for i = 1:numel (ms)
%!   wo = [sin(0.5) 0 cos(0.5)];
%!   E = accumarray (bz * nb + bp + 1, brdf_pdf (ms{i}, repmat (wo, rows (g), 1), g), [nb^2 1]) ...
%!       * (2 / (nb*q)) * (2 * pi / (nb*q)) * n;
%!   wi = brdf_sample (ms{i}, repmat (wo, n, 1), rand (n, 2));
%!   assert (max (abs (sum (wi .^ 2, 2) - 1)) < 1e-12);
%!   iz = min (floor ((wi(:,3) + 1) / 2 * nb), nb - 1);
%!   ip = min (floor (mod (atan2 (wi(:,2), wi(:,1)), 2 * pi) / (2 * pi) * nb), nb - 1);
%!   O = accumarray (iz * nb + ip + 1, 1, [nb^2 1]);
%!   big = E >= 5;                       # bins of small expectation pooled
%!   Eo = [E(big); sum(E(! big))]; Oo = [O(big); sum(O(! big))];
%!   k = Eo > 0;
%!   chi2 = sum ((Oo(k) - Eo(k)) .^ 2 ./ Eo(k));
%!   dof = nnz (k) - 1;
%!   assert (chi2 < dof + 6 * sqrt (2 * dof), sprintf ("%s: chi2 %g, dof %d", names{i}, chi2, dof));
%! endfor
%! rand ("state", state);

%!test
%! ## a sharp lobe (e = 1e6) keeps its angle, and its density is finite
%! m = struct ("rho_d", [0 0 0], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [1e6 1e6 1e6]);
%! wo = repmat ([sin(0.4) 0 cos(0.4)], 100, 1);
%! [wi, p] = brdf_sample (m, wo, rand (100, 2));
%! a = acos (min (wi * [-sin(0.4); 0; cos(0.4)], 1));
%! assert (max (a) < 0.01 && all (isfinite (p)) && median (p) > 1e4);

%!test
%! ## a black model samples the cosine
%! m = struct ("rho_d", [0 0 0], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! [wi, p] = brdf_sample (m, repmat ([0 0 1], 50, 1), rand (50, 2));
%! assert (p, wi(:,3) / pi, 1e-14);

%!test
%! ## many samples of one view: the same draws as the view repeated
%! m = brdf_model ("ggx", "rho_d", [0.1 0.1 0.1], "ks", 1, "alpha", 0.2, "F0", 0.5);
%! wo = [0 0 1; 0.6 0 0.8];
%! own = [1 2 2 1 2].';
%! u = rand (5, 2);
%! [a, pa] = brdf_sample (m, wo, u, own);
%! [b, pb] = brdf_sample (m, wo(own,:), u);
%! assert (a, b, 1e-15);
%! assert (pa, pb, 1e-12);

%!error <Invalid call> brdf_sample (1, 2)
%!error id=lafortune:badOption brdf_sample (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 1], [0.5 2])
%!error id=lafortune:badModel brdf_sample (struct ("type", "ggx", "rho_d", [0 0 0], "ks", [-1 1 1], "alpha", [0.2 0.2 0.2], "F0", [0.5 0.5 0.5]), [0 0 1], [0.5 0.5])
