## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Integration tests of the physically based model types of brdf_model
## ("blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley")
## through material_eval and brdf_model's Jacobian.  The reference, __ref,
## is a second evaluation written here from the published formulas, in
## vector form from wi and wo (h_u = wi + wo, h = h_u / |h_u|), with the
## cancellation-free forms of the same quantities: tan^2 theta_h =
## (h_ux^2 + h_uy^2) / h_uz^2, cos^n theta_h = (1 + tan^2 theta_h)^(-n/2),
## 1 - wi.h = |wi - wo|^2 / (2 (2 + |h_u|)).  Tolerances: 1e-10 relative,
## plus 8 eps K where K = |d log f / d (wi.wo)| (__kappa): an evaluation
## through (cos_i, cos_o, wi.wo) cannot do better than an ulp of wi.wo; only
## sharp lobes near the mirror direction at grazing angles need it.  The
## stiff parameters (test 5) add the ulp of cos theta_h (__kcos) and of
## wi.h (__kwh) in the same way.  Run from the package root with
##   addpath ("inst"); addpath ("src"); test ("test/test_models.m")

%!function f = __ref (m, wi, wo, dc = 0, dh = 0)
%!  ## f = rho_d / pi + the lobes, 0 unless both directions are above the
%!  ## horizon; with dc, cos^2 theta_h divided by 1 + dc; with dh, 1 - wi.h
%!  ## of Schlick's F times 1 + dh
%!  N = rows (wi);
%!  f = zeros (N, 3);
%!  up = wi(:,3) > 0 & wo(:,3) > 0;
%!  a = wi(up,:);
%!  b = wo(up,:);
%!  ci = a(:,3);
%!  co = b(:,3);
%!  hu = a + b;                                    # unnormalised half vector
%!  hn2 = sum (hu .^ 2, 2);
%!  h = hu ./ sqrt (hn2);
%!  ch = h(:,3);                                   # cos theta_h = n.h
%!  t2 = (hu(:,1) .^ 2 + hu(:,2) .^ 2) ./ hu(:,3) .^ 2;   # tan^2 theta_h
%!  if (dc != 0)
%!    t2 += (1 + t2) * dc;
%!  endif
%!  dih = sum (a .* h, 2);                         # wi.h
%!  doh = sum (b .* h, 2);                         # wo.h
%!  omd = sum ((a - b) .^ 2, 2) ./ (2 * (2 + sqrt (hn2))) * (1 + dh);   # 1 - wi.h
%!  ti2 = (a(:,1) .^ 2 + a(:,2) .^ 2) ./ ci .^ 2;  # tan^2 theta_i
%!  to2 = (b(:,1) .^ 2 + b(:,2) .^ 2) ./ co .^ 2;  # tan^2 theta_o
%!  for c = 1:3
%!    v = m.rho_d(c) / pi * ones (rows (a), 1);
%!    for l = 1:rows (m.ks)
%!      ks = m.ks(l,c);
%!      switch (m.type)
%!        case "blinnphong"
%!          n = m.n(l,c);
%!          lobe = ks * (n + 2) / (2 * pi) * exp (-n / 2 * log1p (t2));
%!        case "ward"
%!          al = m.alpha(l,c);
%!          lobe = ks * hn2 ./ (pi * al ^ 2 * hu(:,3) .^ 4) .* exp (-t2 / al ^ 2);
%!        case "cooktorrance"
%!          mm = m.m(l,c);
%!          F0 = m.F0(l,c);
%!          D = exp (-t2 / mm ^ 2) .* (1 + t2) .^ 2 / mm ^ 2;   # / cos^4 theta_h
%!          G = min (1, min (2 * ch .* co ./ doh, 2 * ch .* ci ./ doh));
%!          F = F0 + (1 - F0) * omd .^ 5;
%!          lobe = ks * D .* G .* F ./ (pi * ci .* co);
%!        case "ggx"
%!          al = m.alpha(l,c);
%!          F0 = m.F0(l,c);
%!          ## alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), (n.h)^2 = 1 / (1 + tan^2)
%!          D = al ^ 2 * (1 + t2) .^ 2 ./ (pi * (al ^ 2 + t2) .^ 2);
%!          ## Lambda = (-1 + sqrt (1 + x)) / 2 = x / (2 (1 + sqrt (1 + x)))
%!          Li = al ^ 2 * ti2 ./ (2 * (1 + sqrt (1 + al ^ 2 * ti2)));
%!          Lo = al ^ 2 * to2 ./ (2 * (1 + sqrt (1 + al ^ 2 * to2)));
%!          G2 = 1 ./ (1 + Li + Lo);
%!          F = F0 + (1 - F0) * omd .^ 5;
%!          lobe = ks * D .* G2 .* F ./ (4 * ci .* co);
%!        case "ashikhminshirley"
%!          n = m.n(l,c);
%!          F0 = m.F0(l,c);
%!          F = F0 + (1 - F0) * omd .^ 5;
%!          lobe = ks * (n + 1) / (8 * pi) * exp (-n / 2 * log1p (t2)) .* F ...
%!                 ./ (dih .* max (ci, co));
%!        otherwise
%!          error ("__ref: no type %s", m.type);
%!      endswitch
%!      v += lobe;
%!    endfor
%!    f(up,c) = v;
%!  endfor
%!endfunction

%!function w = __sph (t, p)
%!  w = [sind(t(:)) .* cosd(p(:)), sind(t(:)) .* sind(p(:)), cosd(t(:))];
%!endfunction

%!function [wi, wo] = __dirs ()
%!  ## random pairs up to 88 degrees, exact and near mirror pairs, grazing
%!  ## pairs, normal incidence, near retro-reflection; all above the horizon
%!  rand ("state", 20260);
%!  n = 240;
%!  wi = __sph (88 * rand (n, 1), 360 * rand (n, 1));
%!  wo = __sph (88 * rand (n, 1), 360 * rand (n, 1));
%!  t = [0; 1; 10; 30; 45; 60; 75; 80; 85; 87; 88];
%!  p = 360 * rand (numel (t), 1);
%!  a = __sph (t, p);
%!  wi = [wi; a];
%!  wo = [wo; -a(:,1), -a(:,2), a(:,3)];           # exact mirror
%!  for d = [1e-6 1e-4 1e-3 1e-2 0.05 0.2]           # near mirror, degrees
%!    tt = min (t + d, 88);
%!    wi = [wi; a; a];
%!    wo = [wo; __sph(tt, p + 180); __sph(max (t - d, 0), p + 180 + d)];
%!  endfor
%!  g = [88; 88; 88; 88; 87.5; 86];
%!  q = [88; 60; 20; 0; 87.9; 88];
%!  wi = [wi; __sph(g, 10 * (1:6)'); a];
%!  wo = [wo; __sph(q, 10 * (1:6)' + [180; 90; 0; 45; 179; 170]); __sph(t, p + 0.01)];
%!  wi = [wi; 0 0 1];
%!  wo = [wo; 0 0 1];
%!endfunction

%!function ms = __models ()
%!  ## per type, 1- and 2-lobe models, channels with their own parameters
%!  ms = {};
%!  ms{end+1} = brdf_model ("blinnphong", "rho_d", 0.1, "ks", 0.8, "n", 20);
%!  ms{end+1} = brdf_model ("blinnphong", "rho_d", [0.1 0.2 0.3], "ks", [0.3 0.5 0.7; 2 1 0.5], ...
%!                          "n", [5 10 50; 200 500 1000]);
%!  ms{end+1} = brdf_model ("blinnphong", "ks", [1 2 3], "n", [0.01 0.5 1]);
%!  ms{end+1} = brdf_model ("ward", "rho_d", 0.05, "ks", 0.5, "alpha", 0.15);
%!  ms{end+1} = brdf_model ("ward", "rho_d", [0.2 0.1 0.05], "ks", [0.2 0.3 0.4; 0.05 0.1 0.02], ...
%!                          "alpha", [0.05 0.1 0.2; 0.3 0.5 0.8]);
%!  ms{end+1} = brdf_model ("cooktorrance", "rho_d", 0.1, "ks", 1, "m", 0.2, "F0", 0.04);
%!  ms{end+1} = brdf_model ("cooktorrance", "rho_d", [0.3 0.2 0.1], "ks", [0.5 1 2; 3 2 1], ...
%!                          "m", [0.05 0.1 0.3; 0.4 0.6 0.9], "F0", [0.02 0.5 0.9; 0.1 0.04 0.3]);
%!  ms{end+1} = brdf_model ("ggx", "rho_d", 0.1, "ks", 1, "alpha", 0.2, "F0", 0.04);
%!  ms{end+1} = brdf_model ("ggx", "rho_d", [0.02 0.04 0.08], "ks", [1 0.5 0.25; 0.1 0.2 0.3], ...
%!                          "alpha", [0.03 0.1 0.25; 0.5 0.8 1.5], "F0", [0.9 0.5 0.04; 0.2 0.02 0.6]);
%!  ms{end+1} = brdf_model ("ashikhminshirley", "rho_d", 0.1, "ks", 1, "n", 100, "F0", 0.05);
%!  ms{end+1} = brdf_model ("ashikhminshirley", "rho_d", [0.1 0.3 0.2], "ks", [0.4 0.6 0.8; 1 2 4], ...
%!                          "n", [2 20 200; 1000 50 5], "F0", [0.03 0.5 0.95; 0.2 0.8 0.01]);
%!endfunction

%!function K = __kappa (m, wi, wo)
%!  ## How well the double inputs determine the value: |d log f / d (wi.wo)|
%!  ## at fixed cos_i, cos_o (wo turned about the normal by +-s), from the
%!  ## reference.  An evaluation through (cos_i, cos_o, wi.wo) rounds wi.wo
%!  ## by an ulp, so it is accurate to about eps * K and not better.
%!  R = __ref (m, wi, wo);
%!  K = zeros (size (R));
%!  for s = [-1 1] * 1e-5
%!    cm = -2 * sin (s / 2) ^ 2;    # cos (s) - 1
%!    sn = sin (s);
%!    dw = [wo(:,1) * cm - wo(:,2) * sn, wo(:,1) * sn + wo(:,2) * cm];
%!    w = [wo(:,1:2) + dw, wo(:,3)];
%!    dd = wi(:,1) .* dw(:,1) + wi(:,2) .* dw(:,2);
%!    Rs = max (__ref (m, wi, w), realmin);
%!    K = max (K, abs (log (Rs ./ max (R, realmin))) ./ abs (dd));
%!  endfor
%!  K(! isfinite (K)) = 0;        # dd = 0: normal incidence, wi.wo = cos_o is exact
%!endfunction

%!function K = __kcos (m, wi, wo)
%!  ## |d log f / d log cos theta_h| (of D), from the reference: an evaluation
%!  ## through cos theta_h, rounded to an ulp, is accurate to about eps K and
%!  ## not better (cos^n theta_h: K = n; Beckmann, Ward: K ~ 2 / alpha^2)
%!  R = max (__ref (m, wi, wo), realmin);
%!  K = zeros (size (R));
%!  for dc = [-1 1] * 1e-9
%!    K = max (K, abs (log (max (__ref (m, wi, wo, dc), realmin) ./ R)) / (abs (dc) / 2));
%!  endfor
%!endfunction

%!function K = __kwh (m, wi, wo)
%!  ## |d log f / d log wi.h| through 1 - wi.h in Schlick's F, from the
%!  ## reference: an evaluation through wi.h rounded to an ulp is accurate to
%!  ## about eps K (F0 = 0 near retro-reflection: F = (1 - wi.h)^5, K ~ 5 / (1 - wi.h))
%!  R = max (__ref (m, wi, wo), realmin);
%!  a = wi + wo;
%!  omd = sum ((wi - wo) .^ 2, 2) ./ (2 * (2 + sqrt (sum (a .^ 2, 2))));
%!  K = zeros (size (R));
%!  for dh = [-1 1] * 1e-9
%!    K = max (K, abs (log (max (__ref (m, wi, wo, 0, dh), realmin) ./ R)) / abs (dh));
%!  endfor
%!  K = K ./ max (omd, realmin);      # d log f / d log omd * wi.h / omd, wi.h <= 1
%!endfunction

%!function __close (F, R, tol, what, wi, wo)
%!  ## |F - R| <= tol |R| elementwise (tol a scalar or per element; values
%!  ## below 1e-290, underflow, count as 0); the worst element in the message
%!  err = abs (F - R);
%!  tol = tol .* ones (size (R));
%!  bad = ! (err <= tol .* abs (R) | (abs (F) < 1e-290 & abs (R) < 1e-290));
%!  if (any (bad(:)))
%!    r = err ./ abs (R);
%!    r(! bad) = -Inf;
%!    [~, k] = max (r(:));
%!    [i, c] = ind2sub (size (R), k);
%!    error ("%s: %d bad, worst row %d channel %d (wi %s, wo %s): got %.17g, reference %.17g, rel %.3g, tolerance %.3g",
%!           what, nnz (bad), i, c, mat2str (wi(i,:), 17), mat2str (wo(i,:), 17),
%!           F(k), R(k), r(k), tol(k));
%!  endif
%!endfunction

%!function f = __mirror (m, ci)
%!  ## the closed forms at the exact mirror direction (theta_h = 0, wi.h =
%!  ## wo.h = cos_i = cos_o): D(0), G = 1 (Cook-Torrance), Schlick at cos_i
%!  f = repmat (m.rho_d / pi, numel (ci), 1);
%!  S = @(F0) F0 + (1 - F0) * (1 - ci) .^ 5;
%!  for c = 1:3
%!    for l = 1:rows (m.ks)
%!      ks = m.ks(l,c);
%!      switch (m.type)
%!        case "blinnphong"
%!          lobe = ks * (m.n(l,c) + 2) / (2 * pi) * ones (size (ci));
%!        case "ward"
%!          lobe = ks ./ (4 * pi * m.alpha(l,c) ^ 2 * ci .^ 2);
%!        case "cooktorrance"
%!          lobe = ks * S (m.F0(l,c)) ./ (pi * m.m(l,c) ^ 2 * ci .^ 2);
%!        case "ggx"
%!          al = m.alpha(l,c);
%!          L = (-1 + sqrt (1 + al ^ 2 * (1 - ci .^ 2) ./ ci .^ 2)) / 2;
%!          lobe = ks * S (m.F0(l,c)) ./ (1 + 2 * L) ./ (4 * pi * al ^ 2 * ci .^ 2);
%!        case "ashikhminshirley"
%!          lobe = ks * (m.n(l,c) + 1) / (8 * pi) * S (m.F0(l,c)) ./ ci .^ 2;
%!      endswitch
%!      f(:,c) += lobe;
%!    endfor
%!  endfor
%!endfunction

%!shared wi, wo, ms
%! [wi, wo] = __dirs ();
%! ms = __models ();

%!test
%! ## 1. material_eval against the reference, every type, 1 and 2 lobes: 1e-10
%! ## relative, and 8 eps K more where the value is that ill-determined by
%! ## the inputs (sharp lobes near the mirror direction at grazing angles)
%! assert (rows (wi) >= 300);
%! assert (all (wi(:,3) > 0 & wo(:,3) > 0));
%! types = {};
%! for k = 1:numel (ms)
%!   m = ms{k};
%!   types{end+1} = m.type;
%!   F = material_eval (m, wi, wo);
%!   assert (size (F), [rows(wi) 3]);
%!   K = __kappa (m, wi, wo);
%!   __close (F, __ref (m, wi, wo), 1e-10 + 8 * eps * K, sprintf ("model %d (%s)", k, m.type), wi, wo);
%! endfor
%! assert (unique (types), sort ({"blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"}));

%!test
%! ## 2. reciprocity
%! for k = 1:numel (ms)
%!   m = ms{k};
%!   F = material_eval (m, wi, wo);
%!   B = material_eval (m, wo, wi);
%!   __close (B, F, 1e-12, sprintf ("reciprocity, model %d (%s)", k, m.type), wi, wo);
%! endfor

%!test
%! ## 3. non-negative, finite, real; exactly 0 on and below the horizon
%! rand ("state", 5);
%! n = 200;
%! a = __sph (180 * rand (n, 1), 360 * rand (n, 1));
%! b = __sph (180 * rand (n, 1), 360 * rand (n, 1));
%! a = [a; 1 0 0; 0.6 0 -0.8; 0 0 1; 0.6 0 0.8; 0 0 -1; 0.6 0 0.8];
%! b = [b; 0 0 1; -0.6 0 0.8; 0 1 0; -0.6 0 -0.8; 0 0 -1; -1 0 0];
%! below = a(:,3) <= 0 | b(:,3) <= 0;
%! assert (nnz (below) > 100 && nnz (! below) > 20);
%! for k = 1:numel (ms)
%!   m = ms{k};
%!   F = material_eval (m, a, b);
%!   assert (isreal (F) && all (isfinite (F(:))) && all (F(:) >= 0), "model %d (%s)", k, m.type);
%!   assert (all (all (F(below,:) == 0)), "model %d (%s): not 0 below the horizon", k, m.type);
%!   assert (all (all (F(! below,:) >= m.rho_d / pi)));
%!   K = __kappa (m, a, b);
%!   __close (F, __ref (m, a, b), 1e-10 + 8 * eps * K, sprintf ("model %d (%s), whole sphere", k, m.type), a, b);
%! endfor

%!test
%! ## 4. the Jacobian by channel c's parameters against central differences;
%! ## d/d rho_d = 1/pi and ks d/d ks = the lobe (against the reference)
%! for k = 1:numel (ms)
%!   m = ms{k};
%!   d = brdf_model (m.type);
%!   nl = rows (m.ks);
%!   R = __ref (m, wi, wo);
%!   K = __kappa (m, wi, wo);
%!   for c = 1:3
%!     [f, J] = brdf_model (m, wi, wo, c);
%!     __close (f, R(:,c), 1e-10 + 8 * eps * K(:,c), sprintf ("brdf_model, model %d (%s) channel %d", k, m.type, c), wi, wo);
%!     np = 1 + nl * (numel (d.fields) - 1);
%!     assert (size (J), [rows(wi) np]);
%!     assert (J(:,1), ones (rows (wi), 1) / pi, 1e-15);
%!     j = 1;
%!     for l = 1:nl
%!       for q = 2:numel (d.fields)
%!         j += 1;
%!         fld = d.fields{q};
%!         p = m.(fld)(l,c);
%!         if (strcmp (fld, "ks"))
%!           m1 = m;
%!           m1.rho_d(:) = 0;
%!           m1.ks(:) = 0;
%!           m1.ks(l,c) = p;
%!           K1 = __kappa (m1, wi, wo);
%!           __close (J(:,j) * p, __ref (m1, wi, wo)(:,c), 1e-10 + 8 * eps * K1(:,c),
%!                    sprintf ("ks dF/dks, model %d lobe %d channel %d", k, l, c), wi, wo);
%!         endif
%!         hs = 1e-6 * max (abs (p), 1);
%!         if (strcmp (fld, "n"))
%!           hs = 1e-6 * abs (p);
%!         endif
%!         mp = m;
%!         mn = m;
%!         mp.(fld)(l,c) += hs;
%!         if (p - hs >= d.lo(q-1))
%!           mn.(fld)(l,c) -= hs;
%!           fd = (brdf_model (mp, wi, wo, c) - brdf_model (mn, wi, wo, c)) / (2 * hs);
%!         else                            # at the lower bound: one-sided, 2nd order
%!           mn.(fld)(l,c) += 2 * hs;
%!           fd = (4 * brdf_model (mp, wi, wo, c) - 3 * f - brdf_model (mn, wi, wo, c)) / (2 * hs);
%!         endif
%!         err = abs (J(:,j) - fd);
%!         ## truncation, and the rounding of f (whose other terms may be large) / hs
%!         tol = 1e-6 * abs (fd) + 1e-7 * max (abs (fd)) + 8 * eps * abs (f) / hs + 1e-12;
%!         [e, i] = max (err - tol);
%!         assert (e <= 0, "model %d (%s) channel %d lobe %d %s: J %.10g, differences %.10g (wi %s, wo %s)",
%!                 k, m.type, c, l, fld, J(i,j), fd(i), mat2str (wi(i,:), 6), mat2str (wo(i,:), 6));
%!       endfor
%!     endfor
%!     assert (j, np);
%!   endfor
%! endfor

%!test
%! ## 5. stiff parameters, at and inside the bounds: roughness 1e-4 .. 10,
%! ## exponents 1e-2 .. 1e7, F0 0 .. 1, ks 1e-6 and 1e4 (values over ten
%! ## decades and more): finite, real, non-negative, the reference within
%! ## what the inputs determine, and the closed form at the exact mirror
%! t = [0; 30; 60; 85];
%! a = __sph (t, [0; 40; 200; 310]);
%! ci = a(:,3);
%! A = [wi; a];
%! B = [wo; -a(:,1), -a(:,2), a(:,3)];              # the last 4: exact mirror
%! mir = rows (wi) + (1:4);
%! stiff = {"blinnphong", "n", [1e-2 1 1e5 1e6 1e7], 10;
%!          "ward", "alpha", [1e-4 0.005 1 10], 0.3;
%!          "cooktorrance", "m", [1e-4 0.005 1 10], 0.3;
%!          "ggx", "alpha", [1e-4 0.005 1 10], 0.3;
%!          "ashikhminshirley", "n", [1e-2 1 1e5 1e6 1e7], 10};
%! nm = 0;
%! for i = 1:rows (stiff)
%!   [type, shape, vals, mid] = stiff{i,:};
%!   d = brdf_model (type);
%!   F0s = NaN;
%!   if (any (strcmp (d.fields, "F0")))
%!     F0s = [0 1e-6 1-1e-6 1];
%!   endif
%!   for v = vals
%!     for F0 = F0s
%!       args = {"ks", [1e-6 1 1e4; 0 0 1e-6], shape, [v v v; mid mid mid]};
%!       if (! isnan (F0))
%!         args(end+1:end+2) = {"F0", F0};
%!       endif
%!       m = brdf_model (type, args{:});
%!       what = sprintf ("%s %s = %g F0 = %g", type, shape, v, F0);
%!       F = material_eval (m, A, B);
%!       assert (isreal (F) && all (isfinite (F(:))) && all (F(:) >= 0), "%s: not finite, real, >= 0", what);
%!       R = __ref (m, A, B);
%!       ## besides 8 eps K: the rounding of cos theta_h (n = 1e7: 2e-9,
%!       ## alpha = 1e-4: 4e-8) and of wi.h (F0 = 0 near retro-reflection)
%!       tol = 1e-10 + 8 * eps * __kappa (m, A, B) + 2 * eps * __kcos (m, A, B) ...
%!             + 2 * eps * __kwh (m, A, B);
%!       __close (F, R, tol, what, A, B);
%!       C = __mirror (m, ci);
%!       __close (R(mir,:), C, 1e-12, [what ", reference at the mirror"], A(mir,:), B(mir,:));
%!       __close (F(mir,:), C, tol(mir,:), [what ", at the mirror"], A(mir,:), B(mir,:));
%!       ## one lobe, ks 1e-6 and 1: the same values times 1e6
%!       k = F(:,2) > 1e-280;
%!       __close (1e6 * F(k,1), F(k,2), 1e-13, [what ", ks 1e-6 against 1"], A(k,:), B(k,:));
%!       assert (F(mir,3) >= 1e4 * F(mir,2) * (1 - 1e-12));
%!       nm += 1;
%!     endfor
%!   endfor
%! endfor
%! assert (nm, 5 + 4 + 16 + 16 + 20);
%! ## the jacobian stays finite at stiff interior parameters
%! for i = 1:rows (stiff)
%!   [type, shape, vals, mid] = stiff{i,:};
%!   args = {"ks", [1e-6 1 1e4], shape, [vals(2) mid vals(end-1)]};
%!   if (any (strcmp (brdf_model (type).fields, "F0")))
%!     args(end+1:end+2) = {"F0", [1e-6 0.5 1-1e-6]};
%!   endif
%!   m = brdf_model (type, args{:});
%!   for c = 1:3
%!     [f, J] = brdf_model (m, A, B, c);
%!     assert (all (isfinite ([f(:); J(:)])) && isreal (J), "%s channel %d: Jacobian not finite", type, c);
%!   endfor
%! endfor

## 6. bad input
%!error id=lafortune:badModel brdf_model ("blinnphong", "ks", 1, "n", 1e-3)
%!error id=lafortune:badModel brdf_model ("blinnphong", "ks", 1, "n", 2e7)
%!error id=lafortune:badModel brdf_model ("ward", "ks", 1, "alpha", 5e-5)
%!error id=lafortune:badModel brdf_model ("ward", "ks", 1, "alpha", 10.5)
%!error id=lafortune:badModel brdf_model ("ward", "ks", 1, "alpha", Inf)
%!error id=lafortune:badModel brdf_model ("cooktorrance", "ks", 1, "m", 0, "F0", 0.5)
%!error id=lafortune:badModel brdf_model ("cooktorrance", "ks", 1, "m", 0.1, "F0", -0.01)
%!error id=lafortune:badModel brdf_model ("ggx", "ks", -1e-9, "alpha", 0.1)
%!error id=lafortune:badModel brdf_model ("ggx", "ks", NaN, "alpha", 0.1)
%!error id=lafortune:badModel brdf_model ("ggx", "rho_d", -0.1, "ks", 1, "alpha", 0.1)
%!error id=lafortune:badModel brdf_model ("ggx", "ks", 1, "alpha", [0.1; 11], "F0", 0.04)
%!error id=lafortune:badModel brdf_model ("ggx", "ks", 1, "alpha", 0.1, "F0", 1 + 1e-12)
%!error id=lafortune:badModel brdf_model ("ashikhminshirley", "ks", 1, "n", 10, "F0", [0.1 0.2 1.1])
%!error id=lafortune:badModel brdf_model ("ashikhminshirley", "ks", 1, "n", 0)
%!error id=lafortune:badModel material_eval (struct ("type", "ggx", "rho_d", [0 0 0], "ks", [1 1 1], "alpha", [0.1 0.1 0.1]), [0 0 1], [0 0 1])
%!error id=lafortune:badModel brdf_model (struct ("type", "ggx", "rho_d", [0 0 0], "ks", [1 1 1], "F0", [0 0 0]), [0 0 1], [0 0 1], 1)
%!error id=lafortune:badModel material_eval (struct ("type", "ggx", "rho_d", [0 0 0], "ks", [1 1 1], "alpha", [0 0.1 0.1], "F0", [0 0 0]), [0 0 1], [0 0 1])
%!error id=lafortune:badModelType brdf_model ("beckmann")
%!error id=lafortune:badModelType brdf_model ("beckmann", "ks", 1)
%!error id=lafortune:badModelType material_eval (struct ("type", "phong", "rho_d", [0 0 0], "ks", [1 1 1]), [0 0 1], [0 0 1])
%!error id=lafortune:badDirections brdf_model (brdf_model ("ggx", "ks", 1, "alpha", 0.1), [0.6 0 -0.8], [0 0 1], 1)
