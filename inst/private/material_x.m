## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{f} =} material_x (@var{material}, @var{X})
## An isotropic material at @var{X} = [cos theta_i, cos theta_o, wi . wo]
## (N x 3, both cosines > 0), N x 3 RGB (private, for @code{rt_render}'s
## light samples: the three numbers are all an isotropic BRDF depends on,
## so a trace keeps them and not the directions).  A Lafortune model goes
## through @code{lafortune_core} (ux vx + uy vy = wi . wo - cos ti cos to),
## another type through @code{model_core}, a MERL material through
## @code{merl_eval} at the directions wi = (sin ti, 0, cos ti) and wo at
## the azimuth that gives wi . wo.
## @end deftypefn
function f = material_x (material, X)
  n = rows (X);
  f = zeros (n, 3);
  if (n == 0)
    return;
  endif
  switch (material_kind (material))
    case "lafortune"
      material = check_model (material, "material_x", "lafortune");
      sz = X(:,1) .* X(:,2);
      sxy = X(:,3) - sz;
      for c = 1:3
        p = [material.rho_d(c); reshape([material.Cxy(:,c) material.Cz(:,c) material.e(:,c)].', [], 1)];
        f(:,c) = lafortune_core (p, sxy, sz);
      endfor
    case "model"
      [material, def] = check_model (material, "material_x");
      for c = 1:3
        f(:,c) = model_core (def, model_pack (material, def, c), X);
      endfor
    case "merl"
      si = sqrt (max (1 - X(:,1) .^ 2, 0));
      so = sqrt (max (1 - X(:,2) .^ 2, 0));
      cp = (X(:,3) - X(:,1) .* X(:,2)) ./ max (si .* so, realmin);
      cp = min (max (cp, -1), 1);
      cp(si .* so == 0) = 1;
      sp = sqrt (1 - cp .^ 2);
      wi = [si, zeros(n, 1), X(:,1)];
      wo = [so .* cp, so .* sp, X(:,2)];
      f = merl_eval (material, wi, wo);
  endswitch
endfunction
