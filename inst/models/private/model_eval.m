## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{f} =} model_eval (@var{model}, @var{def}, @var{wi}, @var{wo})
## A checked physically based model (@code{check_model}) at the direction
## pairs @var{wi}, @var{wo} (N x 3, checked): N x 3, 0 on or below the
## horizon, each channel by @code{model_core}.
## @end deftypefn

function f = model_eval (model, def, wi, wo)
  above = wi(:,3) > 0 & wo(:,3) > 0;
  X = [wi(above,3), wo(above,3), sum(wi(above,:) .* wo(above,:), 2)];
  f = zeros (rows (wi), 3);
  for c = 1:3
    f(above,c) = __lafortune_model_core__ (def, __lafortune_model_pack__ (model, def, c), X);
  endfor
endfunction
