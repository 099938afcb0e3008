## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} __lafortune_model_pack__ (@var{model}, @var{def}, @var{c})
## @deftypefnx {} {@var{model} =} __lafortune_model_pack__ (@var{P}, @var{def})
## Channel @var{c} of a model struct as the parameter vector of
## @code{model_core} ([rho_d; ks_1; q_1; ...], lobe after lobe), or the
## model struct of the columns of @var{P} (one per channel R, G, B; a
## physically based type's with its field @code{type}, a Lafortune model's
## without, as Lafortune models have always been).  The one place the
## layout is written.
## @end deftypefn

function out = __lafortune_model_pack__ (in, def, c)
  f = def.fields;
  m = numel (f) - 1;
  if (nargin == 3)
    L = zeros (rows (in.(f{2})), m);
    for j = 1:m
      L(:,j) = in.(f{j+1})(:,c);
    endfor
    out = [in.rho_d(c); reshape(L.', [], 1)];
    return;
  endif
  P = in;
  nl = (rows (P) - 1) / m;
  if (isempty (def.lobe))                # Lafortune: no type field
    out = struct ("rho_d", P(1,:));
  else
    out = struct ("type", def.type, "rho_d", P(1,:));
  endif
  for j = 1:m
    out.(f{j+1}) = P(1 + j + m * (0:nl-1), :);
  endfor
endfunction
