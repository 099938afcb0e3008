## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{a} =} brdf_albedo (@var{model})
## @deftypefnx {lafortune} {@var{a} =} brdf_albedo (@var{model}, @var{theta})
## @deftypefnx {lafortune} {[@var{a}, @var{theta}] =} brdf_albedo (@dots{})
## The directional albedo of a physically based model: the fraction of the
## light arriving from incidence angle theta that the surface reflects,
## a(theta) = integral over the hemisphere of f (wi, wo) cos theta_o d omega_o,
## per channel.  A model conserves energy when a <= 1 at every incidence.
##
## @var{model} is a model struct of a physically based type
## (@code{brdf_model}); @var{theta} the incidence angles in degrees
## (default 0 to 89 in steps of 1).  @var{a} is numel (@var{theta}) x 3.
## The Lambertian term contributes rho_d exactly; each lobe is integrated by
## quadrature over the half vector, on nodes dense where the lobe lives (its
## roughness or exponent) and along its tail to the horizon, so that sharp
## lobes are integrated as accurately as broad ones.  @code{brdf_fit} reports the largest albedo of every fit.
##
## Errors: @code{lafortune:badModel}, @code{lafortune:badModelType} (a
## Lafortune model), @code{lafortune:badOption}.
##
## @example
## @group
## m = brdf_model ("ggx", "ks", 1, "alpha", 0.3, "F0", 1);
## [a, t] = brdf_albedo (m, [0 30 60 85]);
## [t(:) a(:,1)]          # below 1: single scattering loses energy
## @end group
## @end example
## @seealso{brdf_model, brdf_fit, material_eval}
## @end deftypefn

function [a, theta] = brdf_albedo (model, theta = 0:89)
  if (nargin < 1)
    print_usage ();
  endif
  [model, def] = __lafortune_check_model__ (model, "brdf_albedo");
  if (isempty (def.lobe))
    error ("lafortune:badModelType",
           "brdf_albedo: MODEL must be a physically based model (see brdf_model), got a Lafortune model");
  endif
  if (! (isnumeric (theta) && isreal (theta) && ! isempty (theta) && all (isfinite (theta(:)))
         && all (theta(:) >= 0 & theta(:) < 90)))
    error ("lafortune:badOption", "brdf_albedo: THETA must be angles in degrees in [0, 90)");
  endif
  theta = double (theta(:));
  a = zeros (numel (theta), 3);
  for c = 1:3
    a(:,c) = model_albedo (def, __lafortune_model_pack__ (model, def, c), theta * pi / 180);
  endfor
endfunction

%!test
%! ## a Lambertian surface reflects rho_d at every incidence
%! m = brdf_model ("ggx", "rho_d", [0.2 0.5 1]);
%! assert (brdf_albedo (m, [0 45 80]), repmat ([0.2 0.5 1], 3, 1), 1e-15);

%!test
%! ## the microfacet distributions are normalised: at normal incidence a
%! ## smooth mirror (F0 = 1) reflects about everything, whatever its roughness
%! for a = [0.005 0.02 0.1]
%!   g = brdf_albedo (brdf_model ("ggx", "ks", 1, "alpha", a, "F0", 1), 0);
%!   assert (g(1), 1, 0.01 + a);
%!   c = brdf_albedo (brdf_model ("cooktorrance", "ks", 1/4, "m", a, "F0", 1), 0);
%!   assert (c(1), 1, 0.01 + a);          # Ngan's D has no 1/pi, G F/(pi ci co): ks 1/4
%! endfor
%! b = brdf_albedo (brdf_model ("blinnphong", "ks", 1/4, "n", 1e4), 0);
%! assert (b(1), 1, 0.02);               # (n+2)/(2 pi) normalises the lobe over h: ks 1/4
%! s = brdf_albedo (brdf_model ("ashikhminshirley", "ks", 1, "n", 1e4, "F0", 1), 0);
%! assert (s(1), 1, 0.02);

%!test
%! ## GGX with alpha = 1 at normal incidence: D = 1/pi, G2 = 2 co/(1 + co),
%! ## so a(0) = integral of mu/(1 + mu) over [0, 1] = 1 - log (2)
%! [a, t] = brdf_albedo (brdf_model ("ggx", "ks", 1, "alpha", 1, "F0", 1));
%! assert (a(1,1), 1 - log (2), 2e-4);    # the horizon cuts an interval: about 1e-4
%! assert (all (a(:,1) <= 1) && all (a(:,1) > 0.3));
%! assert (t, (0:89)');

%!test
%! ## the sharpest lobes the bounds allow, heavy tail or not: a smooth mirror
%! ## (F0 = 1) at normal incidence reflects everything (G2 -> 1, D
%! ## normalised); GGX's tail, 1.5% of the lobe beyond tan theta_h = 8 alpha,
%! ## was missed by nodes that stopped following it there (0.9976)
%! g = brdf_albedo (brdf_model ("ggx", "ks", 1, "alpha", 1e-4, "F0", 1), [0 40]);
%! assert (g(:,1), [1; 1], 1e-6);
%! w = brdf_albedo (brdf_model ("ward", "ks", 1, "alpha", 1e-4), [0 40]);
%! assert (w(:,1), [1; 1], 1e-6);
%! c = brdf_albedo (brdf_model ("cooktorrance", "ks", 1/4, "m", 1e-4, "F0", 1), [0 40]);
%! assert (c(:,1), [1; 1], 1e-6);

%!error <Invalid call> brdf_albedo ()
%!error id=lafortune:badModelType brdf_albedo (struct ("rho_d", [0 0 0], "Cxy", [], "Cz", [], "e", []))
%!error id=lafortune:badOption brdf_albedo (brdf_model ("ggx", "rho_d", 0.1), 90)
%!error id=lafortune:badModel brdf_albedo (struct ("type", "ggx"))
