## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{p} =} brdf_pdf (@var{D}, @var{wo}, @var{wi})
## @deftypefnx {lafortune} {@var{p} =} brdf_pdf (@var{D}, @var{wo}, @var{wi}, @var{own})
## The density in solid angle with which @code{brdf_sample} draws the
## directions @var{wi} for the viewing directions @var{wo}.
##
## @var{D} is a density of @code{brdf_density}, or a model (its density is
## made on each call); @var{wo} and @var{wi} are N x 3 unit directions in
## the local frame (z = normal).  @var{p} is N x 1: the mixture of the
## cosine-weighted hemisphere (weight rho_d) and each lobe's own sampling
## density (see @code{brdf_sample}), so that it integrates to 1 over the
## sphere of @var{wi} for every @var{wo}.  With @var{own} (N x 1 indices
## into the rows of @var{wo}) the direction @var{wi}(i,:) is seen from
## @var{wo}(@var{own}(i),:): many samples of one view share its mixture,
## made once.
##
## Errors: those of @code{brdf_density}, and @code{lafortune:badDirections}
## for directions that are not N x 3, real and finite, of one size (or
## @var{own} not indices into the rows of @var{wo}).
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

function p = brdf_pdf (D, wo, wi, own = [])
  if (nargin < 3 || nargin > 4)
    print_usage ();
  endif
  D = brdf_density (D);
  own = __lafortune_check_views__ (wo, wi, own, "brdf_pdf");
  M = density_mix (D, wo);             # once per view
  wo = wo(own,:);
  p = zeros (rows (wi), 1);
  for j = 1:columns (M.W)
    w = M.W(own,j);
    r = find (w > 0);
    if (! isempty (r))
      p(r) += w(r) .* density_eval (M, wo(r,:), wi(r,:), j, own(r));
    endif
  endfor
endfunction

%!test
%! ## a Lambertian model: the cosine density
%! m = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! wi = [0 0 1; 0.6 0 0.8; 0 0 -1];
%! assert (brdf_pdf (m, repmat ([0 0 1], 3, 1), wi), [1; 0.8; 0] / pi, 1e-15);

%!test
%! ## many samples of one view: the same densities as the view repeated
%! m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! wo = [0 0 1; 0.6 0 0.8];
%! wi = randn (7, 3); wi ./= sqrt (sum (wi .^ 2, 2));
%! own = [1 2 2 1 2 1 1].';
%! assert (brdf_pdf (m, wo, wi, own), brdf_pdf (m, wo(own,:), wi), 1e-15);

%!error <Invalid call> brdf_pdf (1, 2)
%!error id=lafortune:badDirections brdf_pdf (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 1], [0 0 1], 2)
%!error id=lafortune:badDirections brdf_pdf (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 1], [0 0])
%!error id=lafortune:badDirections brdf_pdf (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), [0 0 NaN], [0 0 1])
