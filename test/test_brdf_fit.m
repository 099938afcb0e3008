## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## brdf_fit on the physically based models: exact recovery of each model's
## own data (stiff cases included), scale invariance over ten decades, the
## shared colour mode, growing, the energy constraint, Lafortune's path.

%!function S = __table (m, w)
%!  ## in-plane and out-of-plane pairs, dense around the mirror direction at
%!  ## the lobe's width W, and a coarse in-plane grid
%!  [ti, dt, dp] = ndgrid ([5 20 35 50 65 75] * pi / 180, w * [-4 -2 -1 -0.5 0 0.5 1 2 4], ...
%!                         w * [-3 -1 0 1 3]);
%!  wi = [sin(ti(:)) zeros(numel (ti), 1) cos(ti(:))];
%!  to = ti(:) + dt(:);
%!  po = pi + dp(:) ./ max (sin (to), 1e-3);
%!  wo = [sin(to) .* cos(po) sin(to) .* sin(po) cos(to)];
%!  [a, b] = ndgrid ((5:10:85) * pi / 180, (-85:10:85) * pi / 180);
%!  wi = [wi; sin(a(:)) zeros(numel (a), 1) cos(a(:))];
%!  wo = [wo; -sin(b(:)) zeros(numel (b), 1) cos(b(:))];
%!  k = wo(:,3) > 0.01;
%!  S = struct ("wi", wi(k,:), "wo", wo(k,:));
%!  S.rgb = material_eval (m, S.wi, S.wo);
%!endfunction

%!function e = __relerr (f, m, scale)
%!  d = brdf_model (m.type);
%!  e = max (abs (f.rho_d / scale - m.rho_d) ./ max (m.rho_d, 1e-3));
%!  for j = 2:numel (d.fields)
%!    s = merge (j == 2, scale, 1);
%!    v = m.(d.fields{j});
%!    e = max (e, max (abs (f.(d.fields{j})(:) / s - v(:)) ./ max (abs (v(:)), 1e-3)));
%!  endfor
%!endfunction

%!test
%! ## every model recovers its own data, from smooth to stiff, and the fit of
%! ## c*y is c times the fit of y for c over ten decades
%! cases = {brdf_model("ggx", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "alpha", 0.3, "F0", 0.05), 0.3
%!          brdf_model("ggx", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "alpha", 0.005, "F0", 0.9), 0.005
%!          brdf_model("ggx", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "alpha", 1, "F0", 0.999), 1
%!          brdf_model("cooktorrance", "rho_d", [0.01 0.2 0.3], "ks", [1 0.5 0.2], "m", 0.143, "F0", 0.001), 0.143
%!          brdf_model("cooktorrance", "rho_d", [0.01 0.2 0.3], "ks", [1 0.5 0.2], "m", 1, "F0", 0), 1
%!          brdf_model("ward", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "alpha", 0.005), 0.005
%!          brdf_model("blinnphong", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "n", 1e4), 0.01
%!          brdf_model("ashikhminshirley", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "n", 50, "F0", 0.5), 0.14};
%! for i = 1:rows (cases)
%!   m = cases{i,1};
%!   S = __table (m, cases{i,2});
%!   for scale = [1 1e-5 1e5]
%!     S2 = S;
%!     S2.rgb *= scale;
%!     [f, info] = brdf_fit (S2, m.type, 1);
%!     e = __relerr (f, m, scale);
%!     assert (e < 1e-5, "%s (width %g, scale %g): parameters off by %g", m.type, cases{i,2}, scale, e);
%!     assert (all (info.rmse / scale < 1e-5 * max (S.rgb)), "%s: rmse %s", m.type, mat2str (info.rmse));
%!     assert (info.type, m.type);
%!   endfor
%! endfor

%!test
%! ## a lobe shared by the channels: the same shape in R, G and B, an
%! ## amplitude each; recovered from data made that way
%! m = brdf_model ("cooktorrance", "rho_d", [0.2 0.05 0.01], "ks", [0.3 0.2 0.1], "m", 0.2, "F0", 0.1);
%! S = __table (m, 0.2);
%! [f, info] = brdf_fit (S, "cooktorrance", 1, "color", "shared");
%! assert (f.m(1,:), [1 1 1] * f.m(1,1));
%! assert (f.F0(1,:), [1 1 1] * f.F0(1,1));
%! assert (__relerr (f, m, 1) < 1e-6);
%! assert (info.color, "shared");

%!test
%! ## growing: the error never rises with more lobes, on data no model
%! ## reproduces (a 2-lobe Lafortune material); every fit finite and
%! ## within its bounds; the trace ends at the reported rmse
%! l = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.6 -0.6 -0.6], ...
%!             "Cz", [1 1 1; 0.7 0.7 0.7], "e", [200 150 100; 6 6 6]);
%! [ti, to] = ndgrid ((0:5:80) * pi / 180, (-80:2:80) * pi / 180);
%! S = struct ("wi", [sin(ti(:)) zeros(numel (ti), 1) cos(ti(:))], ...
%!             "wo", [-sin(to(:)) zeros(numel (ti), 1) cos(to(:))]);
%! S.rgb = material_eval (l, S.wi, S.wo);
%! for t = {"blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"}
%!   [f, info, ms] = brdf_fit (S, t{1}, 3);
%!   assert (all (diff (info.history) <= 1e-12 * info.history(1:end-1,:)), "%s", t{1});
%!   assert (numel (ms), 3);
%!   assert (rows (f.ks), 3);
%!   for c = 1:3
%!     assert (info.trace{c}(end,2), info.rmse(c), 1e-12 * info.rmse(c));
%!   endfor
%!   assert (all (isfinite (info.albedo)));
%!   assert (info.albedo_lobes(3,:), info.albedo);
%!   assert (info.albedo_lobes(1,:), max (brdf_albedo (ms{1}, [0:5:85, 89]), [], 1));
%!   material_eval (f, S.wi, S.wo);                  # checks the bounds
%! endfor

%!test
%! ## energy: the unconstrained fit of a surface that reflects three times
%! ## what it receives says so; with "energy" the fit conserves it (sqp),
%! ## at a larger error
%! m = brdf_model ("ggx", "rho_d", 0.1, "ks", 3, "alpha", 0.3, "F0", 1);
%! [ti, to, ph] = ndgrid ((5:10:85) * pi / 180, (5:10:85) * pi / 180, (0:30:180) * pi / 180);
%! S.wi = [sin(ti(:)) zeros(numel (ti), 1) cos(ti(:))];
%! S.wo = [sin(to(:)) .* cos(ph(:)) sin(to(:)) .* sin(ph(:)) cos(to(:))];
%! S.rgb = material_eval (m, S.wi, S.wo);
%! [f, info] = brdf_fit (S, "ggx", 1, "channels", 1, "tries", 1);
%! assert (info.albedo(1) > 2.9 && ! info.energy(1) && ! info.enforced(1));
%! [g, ginfo] = brdf_fit (S, "ggx", 1, "channels", 1, "tries", 1, "energy", true);
%! assert (ginfo.enforced(1) && ginfo.energy(1));
%! assert (ginfo.albedo(1) <= 1 + 1e-9);
%! assert (ginfo.albedo(1) > 0.99);                  # the constraint is active
%! assert (max (brdf_albedo (g, 0:89)(:,1)) <= 1 + 2e-3);   # also between the angles
%! assert (ginfo.rmse(1) > 100 * info.rmse(1));

%!test
%! ## "lafortune" is lafortune_fit, bit for bit
%! S = merl_plane (merl_standin ("red-plastic"));
%! [a, ia] = brdf_fit (S, "lafortune", 2);
%! b = lafortune_fit (S, 2);
%! assert (isequal (a, b));
%! assert (ia.type, "lafortune");

%!test
%! ## a large table is fitted on the cells of a grid (64 per axis over
%! ## (sqrt (theta_h), theta_d, |cos ti - cos to|)): close to the fit on every
%! ## sample, and on both sides of the reciprocity the cells fold
%! m = brdf_model ("ggx", "rho_d", [0.1 0.2 0.3], "ks", [1 0.5 0.2], "alpha", 0.15, "F0", 0.05);
%! rand ("seed", 3);
%! n = 30000;
%! t = acos (rand (n, 2));
%! p = 2 * pi * rand (n, 1);
%! S.wi = [sin(t(:,1)) zeros(n, 1) cos(t(:,1))];
%! S.wo = [sin(t(:,2)) .* cos(p) sin(t(:,2)) .* sin(p) cos(t(:,2))];
%! S.rgb = material_eval (m, S.wi, S.wo);
%! [g, gi] = brdf_fit (S, "ggx", 1);
%! assert (gi.reduce, "grid 64");
%! assert (gi.groups < n);
%! assert (g.alpha, m.alpha, 0.01 * m.alpha);
%! assert (g.ks, m.ks, 0.02 * max (m.ks));
%! assert (all (gi.rmse < 0.01 * max (S.rgb)));
%! [e, ei] = brdf_fit (S, "ggx", 1, "reduce", "exact");
%! assert (ei.reduce, "exact");
%! assert (e.alpha, m.alpha, 1e-6);
