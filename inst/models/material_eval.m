## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{f} =} material_eval (@var{material}, @var{wi}, @var{wo})
## Evaluate a material, measured or modelled, for pairs of directions.
##
## @var{material} is an analytic model: a Lafortune model struct (field
## @code{Cxy}, no @code{type}; see @code{lafortune_eval}) or a struct with a
## field @code{type} (@code{"blinnphong"}, @code{"ward"},
## @code{"cooktorrance"}, @code{"ggx"}, @code{"ashikhminshirley"}; see
## @code{brdf_model}), or a MERL material struct (fields @code{data},
## @code{valid}; see @code{merl_read}).  @var{wi}, @var{wo} are N x 3 unit
## directions in the local frame (z = normal).  Returns N x 3, 0 on or below
## the horizon for the models.  This is the one dispatch: the renderers, the
## errors, the exports and the pipeline evaluate every material through it.
##
## @example
## @group
## m = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), ...
##             "Cz", zeros (0, 3), "e", zeros (0, 3));
## material_eval (m, [0 0 1], [0 0 1])     # 0.5/pi per channel
## g = brdf_model ("ggx", "rho_d", [0.1 0.05 0.02], "ks", 1, ...
##                 "alpha", 0.2, "F0", 0.04);
## material_eval (g, [0.6 0 0.8], [-0.6 0 0.8])
## @end group
## @end example
## @seealso{brdf_model, lafortune_eval, merl_eval, scene_slice}
## @end deftypefn
function f = material_eval (material, wi, wo)
  if (nargin != 3)
    print_usage ();
  endif
  switch (__lafortune_material_kind__ (material))
    case "lafortune"
      f = lafortune_eval (material, wi, wo);
    case "model"
      [material, def] = __lafortune_check_model__ (material, "material_eval");
      [wi, wo] = __lafortune_check_dirs__ (wi, wo, "material_eval");
      f = model_eval (material, def, wi, wo);
    case "merl"
      f = merl_eval (material, wi, wo);
    otherwise
      error ("lafortune:badMaterial",
             "material_eval: MATERIAL must be an analytic model (a Lafortune model: fields rho_d, Cxy, Cz, e; another type: field type, see brdf_model) or a MERL material (fields data, valid), got %s",
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
