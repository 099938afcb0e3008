## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{f} =} lafortune_eval (@var{model}, @var{wi}, @var{wo})
## Evaluate an isotropic Lafortune BRDF model, per RGB channel.
##
## @var{model} is a struct with fields @code{rho_d} (1 x 3) and @code{Cxy},
## @code{Cz}, @code{e} (nlobes x 3, one column per channel R, G, B).
## @var{wi} (toward the light) and @var{wo} (toward the viewer) are N x 3
## arrays of unit directions in the local frame (z = surface normal); a 1 x 3
## array is expanded.  The result @var{f} is N x 3:
##
## @example
## f = rho_d/pi + sum_k max (Cxy_k (ux vx + uy vy) + Cz_k uz vz, 0) ^ e_k
## @end example
##
## Lobe bases are clamped at 0 before the power (so the result is never
## complex), powers are taken in log space and each lobe is capped at
## exp(300), so the result is finite for any finite input (exponents up to
## 1e6 and more, |C| up to 10 and more).  Directions below the horizon
## (z <= 0 for @var{wi} or @var{wo}) give 0.
##
## @example
## @group
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], ...
##             "Cz", [1 1 1], "e", [20 20 20]);
## wi = [sin(0.5) 0 cos(0.5)];
## f = lafortune_eval (m, wi, [-wi(1:2) wi(3)])   # at the mirror direction
## @end group
## @end example
## @seealso{lafortune_fit, merl_eval, material_eval}
## @end deftypefn
function f = lafortune_eval (model, wi, wo)
  if (nargin != 3)
    print_usage ();
  endif
  model = __lafortune_check_model__ (model, "lafortune_eval", "lafortune");
  [wi, wo] = __lafortune_check_dirs__ (wi, wo, "lafortune_eval");
  sxy = wi(:,1) .* wo(:,1) + wi(:,2) .* wo(:,2);
  sz = wi(:,3) .* wo(:,3);
  above = wi(:,3) > 0 & wo(:,3) > 0;
  f = zeros (rows (wi), 3);
  for c = 1:3
    p = [model.rho_d(c); reshape([model.Cxy(:,c) model.Cz(:,c) model.e(:,c)].', [], 1)];
    ## (above,1): a single row indexed by a false scalar stays 0 x 1, not 0 x 0
    f(above,c) = __lafortune_lafortune_core__ (p, sxy(above,1), sz(above,1));
  endfor
endfunction

%!shared m, wi, wo
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -0.8], ...
%!             "Cz", [1 0.9 0.8], "e", [10 20 30]);
%! t = [0.1; 0.5; 1.0];
%! wi = [sin(t) zeros(3,1) cos(t)];
%! wo = [-sin(t) zeros(3,1) cos(t)];

%!test
%! f = lafortune_eval (m, wi, wo);
%! ## at the mirror direction the base is Cz for Cxy = -Cz
%! expect = m.rho_d / pi + [1 0.9^20 0.8^30] .* ones (3, 1);
%! assert (f, expect, 1e-12);

%!test
%! ## off-mirror: explicit formula
%! wo2 = [0 sin(0.3) cos(0.3)];
%! f = lafortune_eval (m, wi, wo2);
%! for c = 1:3
%!   b = m.Cxy(c) * (wi(:,1:2) * wo2(1:2)') + m.Cz(c) * wi(:,3) * wo2(3);
%!   assert (f(:,c), m.rho_d(c) / pi + max (b, 0) .^ m.e(c), 1e-12);
%! endfor

%!test
%! ## lambertian only, no lobes
%! m0 = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! assert (lafortune_eval (m0, wi, wo), 0.5 / pi * ones (3, 3), 1e-15);

%!test
%! ## negative base never gives complex numbers: retro lobe seen from the mirror side
%! m2 = m; m2.Cxy = [1 1 1]; m2.Cz = [1e-3 1e-3 1e-3]; m2.e = [2.5 3.3 7.1];
%! f = lafortune_eval (m2, wi, wo);
%! assert (isreal (f));
%! assert (f, repmat (m.rho_d / pi, 3, 1), 1e-15);

%!test
%! ## extreme exponents and amplitudes stay finite
%! for e = [1e3 1e4 1e5 1e6 1e8]
%!   for C = [0.5 1 2 10]
%!     mx = struct ("rho_d", [0 0 0], "Cxy", -C * [1 1 1], "Cz", C * [1 1 1], "e", e * [1 1 1]);
%!     f = lafortune_eval (mx, wi, wo);
%!     assert (all (isfinite (f(:))) && isreal (f) && all (f(:) >= 0));
%!   endfor
%! endfor

%!test
%! ## e = 0: a lobe of 1 where the base is positive, 0 elsewhere
%! m0 = struct ("rho_d", [0 0 0], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [0 0 0]);
%! assert (lafortune_eval (m0, wi, wo), ones (3, 3));

%!test
%! ## below the horizon gives 0; single input accepted; 1 x 3 broadcast
%! f = lafortune_eval (m, [0 0 1], single ([0 -sin(0.2) -cos(0.2); 0 0 1]));
%! assert (f(1,:), [0 0 0]);
%! assert (f(2,:), m.rho_d / pi + [1 0.9^20 0.8^30], 1e-6);

%!test
%! ## a single pair above or below the horizon (one row: no 0 x 0 indexing)
%! wa = [sin(0.5) 0 cos(0.5)];
%! assert (lafortune_eval (m, [0 0 1], [0 sin(2) cos(2)]), [0 0 0]);
%! assert (lafortune_eval (m, [0 sin(2) cos(2)], [0 0 1]), [0 0 0]);
%! assert (lafortune_eval (m, [0 0 -1], [0 0 -1]), [0 0 0]);
%! f1 = lafortune_eval (m, wa, [-wa(1:2) wa(3)]);
%! assert (size (f1), [1 3]);
%! assert (f1, m.rho_d / pi + [1 0.9^20 0.8^30], 1e-12);   # mirror: base = Cz
%! ## the horizon itself (z = 0) is below
%! assert (lafortune_eval (m, [1 0 0], [0 0 1]), [0 0 0]);

%!error <Invalid call> lafortune_eval (1, 2)
%!error <no field 'Cz'> lafortune_eval (struct ("rho_d", [1 1 1], "Cxy", [1 1 1], "e", [1 1 1]), [0 0 1], [0 0 1])
%!error <must be NLOBES x 3> lafortune_eval (struct ("rho_d", [1 1 1], "Cxy", [1 1 1], "Cz", [1 1], "e", [1 1 1]), [0 0 1], [0 0 1])
%!error <rho_d must be 1 x 3> lafortune_eval (struct ("rho_d", [1 1], "Cxy", [1 1 1], "Cz", [1 1 1], "e", [1 1 1]), [0 0 1], [0 0 1])
%!error <at most 8> lafortune_eval (struct ("rho_d", [1 1 1], "Cxy", ones (9, 3), "Cz", ones (9, 3), "e", ones (9, 3)), [0 0 1], [0 0 1])
%!error <e must be .= 0> lafortune_eval (struct ("rho_d", [1 1 1], "Cxy", [1 1 1], "Cz", [1 1 1], "e", [-1 1 1]), [0 0 1], [0 0 1])
%!error <real N x 3> lafortune_eval (m, [0 1], [0 0 1])
%!error <real N x 3> lafortune_eval (m, "abc", [0 0 1])
%!error <unit vectors> lafortune_eval (m, [0 0 2], [0 0 1])
%!error <same number of rows> lafortune_eval (m, [0 0 1; 0 0 1], [0 0 1; 0 0 1; 0 0 1])
%!error <finite> lafortune_eval (m, [0 0 NaN], [0 0 1])
%!error id=lafortune:badModel lafortune_eval (struct ("rho_d", [1 1 1]), [0 0 1], [0 0 1])
%!error id=lafortune:notUnit lafortune_eval (m, [0 0 0.5], [0 0 1])
