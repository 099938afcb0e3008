## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{S} =} merl_samples (@var{brdf})
## @deftypefnx {lafortune} {@var{S} =} merl_samples (@var{brdf}, @var{name}, @var{value}, @dots{})
## The whole valid hemisphere of a MERL material as a table of directions,
## for a full (not only in-plane) fit.
##
## Every valid bin whose directions lie above the horizon becomes one sample,
## at its grid point (theta_h = (i/90)^2 pi/2, theta_d = j/90 pi/2,
## phi_d = k/180 pi, phi_h = 0).  Options:
##
## @table @code
## @item "max_angle"
## largest theta_i and theta_o kept, in degrees (default 80, as
## @code{merl_plane}).
## @item "max_samples"
## keep at most this many samples, evenly spaced in bin order (default Inf).
## @end table
##
## @var{S} has the fields of @code{merl_plane}'s result (@code{wi}, @code{wo},
## @code{rgb}, @code{theta_i}, @code{theta_o}, @code{name}) with
## @code{kind} = @code{"hemisphere"} and @code{index}, the bins' indices.
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## S = merl_samples (brdf, "max_samples", 2e5);
## model = lafortune_fit (S, 2);
## @end group
## @end example
## @seealso{merl_plane, lafortune_fit}
## @end deftypefn
function S = merl_samples (brdf, varargin)
  if (nargin < 1)
    print_usage ();
  endif
  check_merl (brdf, "merl_samples");
  opt = parse_opts (varargin, "merl_samples", struct ("max_angle", 80, "max_samples", Inf));
  if (! isscalar (opt.max_angle) || ! (opt.max_angle > 0 && opt.max_angle <= 90))
    error ("lafortune:badOption", "merl_samples: MAX_ANGLE must be a scalar in (0, 90] degrees");
  endif
  if (! isscalar (opt.max_samples) || ! (opt.max_samples >= 1))
    error ("lafortune:badOption", "merl_samples: MAX_SAMPLES must be a scalar >= 1");
  endif
  [wi, wo] = merl_grid ();
  c = cosd (opt.max_angle);
  if (opt.max_angle >= 90)
    c = 1e-12;
  endif
  idx = find (brdf.valid & wi(:,3) >= c & wo(:,3) >= c);
  if (numel (idx) > opt.max_samples)
    idx = idx(unique (round (linspace (1, numel (idx), opt.max_samples))));
  endif
  wi = wi(idx,:); wo = wo(idx,:);
  wi ./= sqrt (sum (wi .^ 2, 2));
  wo ./= sqrt (sum (wo .^ 2, 2));
  name = "";
  if (isfield (brdf, "name"))
    name = brdf.name;
  endif
  S = struct ("wi", wi, "wo", wo, "rgb", brdf.data(idx,:),
              "theta_i", acosd (min (wi(:,3), 1)), "theta_o", acosd (min (wo(:,3), 1)),
              "name", name, "kind", "hemisphere", "index", idx);
endfunction

%!test
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 10 10]);
%! b = merl_synth (m, "missing", 70);
%! S = merl_samples (b);
%! assert (S.kind, "hemisphere");
%! assert (all (b.valid(S.index)));
%! assert (max ([S.theta_i; S.theta_o]) <= 80 + 1e-9);
%! ## the samples sit at the grid points: the model there equals the data
%! assert (S.rgb, lafortune_eval (m, S.wi, S.wo), -1e-9);
%! S2 = merl_samples (b, "max_samples", 1000);
%! assert (numel (S2.index), 1000);
%! assert (all (ismember (S2.index, S.index)));

%!error <Invalid call> merl_samples ()
%!error id=lafortune:badOption merl_samples (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "max_samples", 0)
