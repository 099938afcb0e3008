## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{S} =} merl_plane (@var{brdf})
## @deftypefnx {lafortune} {@var{S} =} merl_plane (@var{brdf}, @var{name}, @var{value}, @dots{})
## The paper's data table: a MERL material sampled in the plane of incidence.
##
## The incident direction is wi = (sin ti, 0, cos ti) with ti >= 0 and the
## outgoing direction wo = (sin to, 0, cos to) with to on both sides of the
## normal: to < 0 is the far side, where to = -ti is the mirror direction.
## The vectors are built from the angles as MERL's reference reader builds
## them (phi_in = 0, phi_out = pi on the far side), so a table at whole
## degrees, whose samples lie on bin edges, gets the reader's bins.
## Grazing angles are left out (the measurements are noisy there) and
## invalid (missing) samples are dropped.  Options:
##
## @table @code
## @item "max_angle"
## largest |ti| and |to| kept, in degrees (default 80: grazing angles beyond
## 80 degrees are left out).
## @item "step"
## spacing of ti and to in degrees (default 1).
## @item "theta_i"
## incident angles in degrees (default 0:step:max_angle).
## @item "method"
## lookup, @code{"nearest"} (default, as the database's reader) or
## @code{"linear"} (see @code{merl_eval}).
## @end table
##
## @var{S} is a struct with fields @code{wi}, @code{wo} (N x 3),
## @code{rgb} (N x 3), @code{theta_i}, @code{theta_o} (N x 1, degrees),
## @code{name} and @code{kind} = @code{"plane"}; @code{lafortune_fit} takes it.
##
## @example
## @group
## brdf = merl_standin ("green-metallic-paint");
## S = merl_plane (brdf, "max_angle", 80);
## k = S.theta_i == 30;
## semilogy (S.theta_o(k), S.rgb(k,2));   # the paper's Fig. 2 data
## @end group
## @end example
## @seealso{merl_samples, lafortune_fit, merl_eval}
## @end deftypefn
function S = merl_plane (brdf, varargin)
  if (nargin < 1)
    print_usage ();
  endif
  __lafortune_check_merl__ (brdf, "merl_plane");
  opt = __lafortune_parse_opts__ (varargin, "merl_plane",
                    struct ("max_angle", 80, "step", 1, "theta_i", [], "method", "nearest"));
  if (! isscalar (opt.max_angle) || ! (opt.max_angle > 0 && opt.max_angle < 90))
    error ("lafortune:badOption", "merl_plane: MAX_ANGLE must be a scalar in (0, 90) degrees");
  endif
  if (! isscalar (opt.step) || ! (opt.step > 0 && opt.step <= opt.max_angle))
    error ("lafortune:badOption", "merl_plane: STEP must be a scalar in (0, MAX_ANGLE] degrees");
  endif
  ti = opt.theta_i;
  if (isempty (ti))
    ti = 0:opt.step:opt.max_angle;
  elseif (! isnumeric (ti) || any (ti(:) < 0 | ti(:) > opt.max_angle))
    error ("lafortune:badOption", "merl_plane: THETA_I must be angles in [0, MAX_ANGLE] degrees");
  endif
  to = [-fliplr(opt.step:opt.step:opt.max_angle), 0:opt.step:opt.max_angle];
  [TI, TO] = ndgrid (ti(:), to(:));
  TI = TI(:); TO = TO(:);
  ## directions built from angles as the reference reader builds them
  ## (phi_in = 0, phi_out = pi on the far side)
  ti_r = TI * pi / 180;
  to_r = abs (TO) * pi / 180;
  fo = pi * (TO < 0);
  wi = [sin(ti_r) .* cos(0), sin(ti_r) .* sin(0), cos(ti_r)];
  wo = [sin(to_r) .* cos(fo), sin(to_r) .* sin(fo), cos(to_r)];
  [rgb, ok] = merl_eval (brdf, wi, wo, opt.method);
  name = "";
  if (isfield (brdf, "name"))
    name = brdf.name;
  endif
  S = struct ("wi", wi(ok,:), "wo", wo(ok,:), "rgb", rgb(ok,:),
              "theta_i", TI(ok), "theta_o", TO(ok), "name", name, "kind", "plane");
endfunction

%!demo
%! ## the paper's Fig. 2 data on a synthetic material (Cook-Torrance stand-in)
%! brdf = merl_standin ("green-metallic-paint");
%! S = merl_plane (brdf);
%! k = S.theta_i == 30;
%! semilogy (S.theta_o(k), S.rgb(k,2), ".");
%! xlabel ("theta_o (deg), mirror at -30"); ylabel ("green channel");

%!test
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 10 10]);
%! b = merl_synth (m, "missing", 85, "missing_fraction", 1);
%! S = merl_plane (b, "step", 5);
%! assert (S.kind, "plane");
%! assert (max (abs ([S.theta_i; S.theta_o])), 80);
%! assert (numel (S.theta_i), 17 * 33);
%! assert (all (abs (sum (S.wi .^ 2, 2) - 1) < 1e-12));
%! ## values follow the model (nearest bin)
%! f = lafortune_eval (m, S.wi, S.wo);
%! assert (median (abs (S.rgb(:) - f(:)) ./ f(:)) < 0.02);
%! ## with max_angle 89, the missing grazing samples are dropped
%! S2 = merl_plane (b, "max_angle", 89, "step", 1);
%! assert (numel (S2.theta_i) < 90 * 179);
%! assert (all (S2.rgb(:) >= 0));

%!error <Invalid call> merl_plane ()
%!error id=lafortune:badMerl merl_plane (1)
%!error id=lafortune:badOption merl_plane (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "max_angle", 95)
%!error id=lafortune:badOption merl_plane (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "step", 0)
%!error <unknown option 'bogus'> merl_plane (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "bogus", 0)
