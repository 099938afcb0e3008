## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{C} =} stability_cases (@var{seed})
## The stiff and extreme tables of the stability checks (test_stability,
## study_stability): a struct array with @code{name}, @code{S} (a sample
## table, possibly one the fitters must refuse) and @code{truth} (the
## Lafortune model the table was made from, or [] when there is none), made
## from synthetic in-plane tables, seeded by @var{seed}.  The cases: noise
## and outliers, a channel of zeros, a single sample, duplicated samples,
## scales 1e-12 and 1e12, only grazing samples, only the mirror direction,
## NaN and Inf entries, one huge weight, an exponent near the bound
## (1e6), rho_d = 0, and a lobe with Cxy = Cz.
## @end deftypefn
function C = stability_cases (seed)
  rand ("seed", seed); randn ("seed", seed);
  base = struct ("rho_d", [0.3 0.1 0.05], "Cxy", -[0.9 1 1.05], "Cz", [0.85 1 0.95],
                 "e", [20 60 200]);
  S0 = plane (base, 0:4:80, -80:4:80);
  C = struct ("name", {}, "S", {}, "truth", {});
  S = S0;  S.rgb .*= max (1 + 0.1 * randn (size (S.rgb)), 0);
  o = rand (rows (S.rgb), 1) < 0.01;  S.rgb(o,:) *= 100;
  C(end+1) = mk ("noise 10% and outliers x100", S, base);
  S = S0;  S.rgb(:,3) = 0;
  zb = base;  zb.rho_d(3) = 0;  zb.Cxy(3) = 0;  zb.Cz(3) = 0;
  C(end+1) = mk ("a channel of zeros", S, zb);
  C(end+1) = mk ("a single sample", rows_of (S0, 100), base);
  C(end+1) = mk ("every sample three times", rows_of (S0, repmat (1:rows (S0.rgb), 1, 3)), base);
  S = S0;  S.rgb *= 1e-12;
  C(end+1) = mk ("scale 1e-12", S, scaled (base, 1e-12));
  S = S0;  S.rgb *= 1e12;
  C(end+1) = mk ("scale 1e12", S, scaled (base, 1e12));
  C(end+1) = mk ("only grazing samples (80-89 degrees)", plane (base, 80:89, [-89:-80, 80:89]), base);
  C(end+1) = mk ("only the mirror direction", mirror (base, 0:2:88), base);
  S = S0;  S.rgb(7,2) = NaN;
  C(end+1) = mk ("a NaN entry", S, base);
  S = S0;  S.rgb(9,1) = Inf;
  C(end+1) = mk ("an Inf entry", S, base);
  S = S0;  S.weight = ones (rows (S.rgb), 1);  S.weight(5) = 1e12;
  C(end+1) = mk ("one weight 1e12", S, base);
  sharp = struct ("rho_d", [0.02 0.02 0.02], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [1e6 1e6 1e6]);
  C(end+1) = mk ("exponent near the bound (1e6)", stiff (sharp), sharp);
  dark = setfield (base, "rho_d", [0 0 0]);
  C(end+1) = mk ("rho_d = 0", plane (dark, 0:4:80, -80:4:80), dark);
  retro = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [1 1 1], "Cz", [1 1 1], "e", [20 20 20]);
  C(end+1) = mk ("a lobe with Cxy = Cz", plane (retro, 0:4:80, -80:4:80), retro);
endfunction

function c = mk (name, S, truth)
  c = struct ("name", name, "S", S, "truth", truth);
endfunction

function S = plane (m, ti, to)
  [TI, TO] = ndgrid (ti, to);
  S = table_of (m, [sind(TI(:)), 0 * TI(:), cosd(TI(:))], [sind(TO(:)), 0 * TO(:), cosd(TO(:))]);
endfunction

function S = mirror (m, t)
  t = t(:);
  S = table_of (m, [sind(t), 0 * t, cosd(t)], [-sind(t), 0 * t, cosd(t)]);
endfunction

## dense samples around the mirror direction, where a sharp lobe lives
function S = stiff (m)
  w = sqrt (2 / m.e(1)) * 180 / pi;
  [TI, D] = ndgrid (5:10:75, [linspace(-6 * w, 6 * w, 61), -80:4:80]);
  TO = max (min (-TI + D, 85), -85);
  S = table_of (m, [sind(TI(:)), 0 * TI(:), cosd(TI(:))], [sind(TO(:)), 0 * TO(:), cosd(TO(:))]);
endfunction

function S = table_of (m, wi, wo)
  S = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (m, wi, wo));
endfunction

function S = rows_of (S, i)
  S = struct ("wi", S.wi(i,:), "wo", S.wo(i,:), "rgb", S.rgb(i,:));
endfunction

function m = scaled (m, s)
  m.rho_d *= s;
  f = s .^ (1 ./ m.e);
  m.Cxy .*= f;  m.Cz .*= f;
endfunction
