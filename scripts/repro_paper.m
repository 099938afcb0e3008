## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} repro_paper (@var{c}, @var{material})
## The paper's PSNR (dB) of @var{material} for each lobe count of LOBES
## (configuration @var{c} from repro_config): 1 x numel (LOBES), NaN where
## the paper has no number (a material or a lobe count it did not fit).
## @end deftypefn
function p = repro_paper (c, material)
  p = nan (1, numel (c.lobes));
  key = repro_field (material);
  if (isfield (c.paper_psnr, key))
    v = c.paper_psnr.(key);
    have = c.lobes <= numel (v);
    p(have) = v(c.lobes(have));
  endif
endfunction
