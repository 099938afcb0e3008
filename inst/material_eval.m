## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{f} =} material_eval (@var{material}, @var{wi}, @var{wo})
## Evaluate a material, measured or modelled, for pairs of directions.
##
## @var{material} is a Lafortune model struct (field @code{Cxy}; see
## @code{lafortune_eval}) or a MERL material struct (fields @code{data},
## @code{valid}; see @code{merl_read}).  @var{wi}, @var{wo} are N x 3 unit
## directions in the local frame (z = normal).  Returns N x 3.  The renderers
## shade through this one function.
##
## @example
## @group
## m = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), ...
##             "Cz", zeros (0, 3), "e", zeros (0, 3));
## material_eval (m, [0 0 1], [0 0 1])     # 0.5/pi per channel
## @end group
## @end example
## @seealso{lafortune_eval, merl_eval, scene_slice}
## @end deftypefn
function f = material_eval (material, wi, wo)
  if (nargin != 3)
    print_usage ();
  endif
  switch (material_kind (material))
    case "lafortune"
      f = lafortune_eval (material, wi, wo);
    case "merl"
      f = merl_eval (material, wi, wo);
    otherwise
      error ("lafortune:badMaterial",
             "material_eval: MATERIAL must be a Lafortune model (fields rho_d, Cxy, Cz, e) or a MERL material (fields data, valid), got %s",
             class (material));
  endswitch
endfunction

%!test
%! m = struct ("rho_d", [0.5 0.2 0.1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! assert (material_eval (m, [0 0 1], [0 0 1]), [0.5 0.2 0.1] / pi, 1e-15);
%! b = merl_synth (m);
%! assert (material_eval (b, [0 0 1], [0 0 1]), [0.5 0.2 0.1] / pi, 1e-15);

%!error <Invalid call> material_eval (1, 2)
%!error id=lafortune:badMaterial material_eval (42, [0 0 1], [0 0 1])
%!error id=lafortune:badMaterial material_eval (struct ("foo", 1), [0 0 1], [0 0 1])
