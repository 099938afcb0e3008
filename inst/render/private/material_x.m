## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{f} =} material_x (@var{material}, @var{X})
## An isotropic material at @var{X} = [cos theta_i, cos theta_o, wi . wo]
## (N x 3, both cosines > 0), N x 3 RGB (private, for @code{rt_render}'s
## light samples: the three numbers are all an isotropic BRDF depends on,
## so a trace keeps them and not the directions).  A Lafortune model goes
## through @code{lafortune_core} (ux vx + uy vy = wi . wo - cos ti cos to),
## another type through @code{model_value} (model_core, compiled), a MERL material through
## @code{merl_eval} at the pair of directions @code{slice_dirs} makes of
## the three (the side of the mirror pair that @code{scene_slice}, so the
## slice tables of both renderers, take).
## @end deftypefn
function f = material_x (material, X)
  n = rows (X);
  f = zeros (n, 3);
  if (n == 0)
    return;
  endif
  switch (__lafortune_material_kind__ (material))
    case "lafortune"
      material = __lafortune_check_model__ (material, "material_x", "lafortune");
      sz = X(:,1) .* X(:,2);
      sxy = X(:,3) - sz;
      for c = 1:3
        p = [material.rho_d(c); reshape([material.Cxy(:,c) material.Cz(:,c) material.e(:,c)].', [], 1)];
        f(:,c) = __lafortune_lafortune_core__ (p, sxy, sz);
      endfor
    case "model"
      [material, def] = __lafortune_check_model__ (material, "material_x");
      for c = 1:3
        f(:,c) = model_value (def, __lafortune_model_pack__ (material, def, c), X);
      endfor
    case "merl"
      ## the pair as scene_slice builds it (slice_dirs: wo in the xz plane,
      ## wi at the azimuth that gives wi . wo): a measured table is not
      ## exactly mirror-symmetric, and both renderers' tables take this side
      [wi, wo] = __lafortune_slice_dirs__ (acos (min (X(:,1), 1)), acos (min (X(:,2), 1)), X(:,3));
      f = merl_eval (material, wi, wo);
  endswitch
endfunction
