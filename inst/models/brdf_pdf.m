## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {lafortune} {@var{p} =} brdf_pdf (@var{D}, @var{wo}, @var{wi})
## The density in solid angle with which @code{brdf_sample} draws the
## directions @var{wi} for the viewing directions @var{wo}.
##
## @var{D} is a density of @code{brdf_density}, or a model (its density is
## made on each call); @var{wo} and @var{wi} are N x 3 unit directions in
## the local frame (z = normal).  @var{p} is N x 1: the mixture of the
## cosine-weighted hemisphere (weight rho_d) and each lobe's own sampling
## density (see @code{brdf_sample}), so that it integrates to 1 over the
## sphere of @var{wi} for every @var{wo}.
##
## Errors: those of @code{brdf_density}, and @code{lafortune:badDirections}
## for directions that are not N x 3, real and finite, of one size.
##
## @example
## @group
## D = brdf_density (brdf_model ("ggx", "ks", 1, "alpha", 0.2, "F0", 0.05));
## wo = [0 0 1];
## brdf_pdf (D, wo, [0 0 1])       # the mirror direction: the lobe's peak
## brdf_pdf (D, wo, [1 0 0])       # grazing: the diffuse part's zero
## @end group
## @end example
## @seealso{brdf_sample, brdf_density}
## @end deftypefn

function p = brdf_pdf (D, wo, wi)
  if (nargin != 3)
    print_usage ();
  endif
  D = brdf_density (D);
  check_pair (wo, wi, "brdf_pdf");
  M = density_mix (D, wo);
  p = zeros (rows (wi), 1);
  for j = 1:columns (M.W)
    w = M.W(:,j);
    r = w > 0;
    if (all (r))
      p += w .* density_eval (M, wo, wi, j, r);
    elseif (any (r))
      p(r) += w(r) .* density_eval (M, wo(r,:), wi(r,:), j, r);
    endif
  endfor
endfunction

function check_pair (wo, wi, fname)
  if (! (isnumeric (wo) && isnumeric (wi) && isreal (wo) && isreal (wi) && columns (wo) == 3
         && isequal (size (wo), size (wi)) && all (isfinite ([wo(:); wi(:)]))))
    error ("lafortune:badDirections",
           "%s: WO and WI must be real, finite N x 3 arrays of one size, got %s and %s",
           fname, mat2str (size (wo)), mat2str (size (wi)));
  endif
endfunction

%!test
%! ## a Lambertian model: the cosine density
%! m = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! wi = [0 0 1; 0.6 0 0.8; 0 0 -1];
%! assert (brdf_pdf (m, repmat ([0 0 1], 3, 1), wi), [1; 0.8; 0] / pi, 1e-15);

%!error <Invalid call> brdf_pdf (1, 2)
%!error id=lafortune:badDirections brdf_pdf (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 1], [0 0])
%!error id=lafortune:badDirections brdf_pdf (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 NaN], [0 0 1])
