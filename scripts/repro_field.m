## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{f} =} repro_field (@var{material})
## The field name under which the pipeline's structs (summary.json, the
## paper's table of config.mk) keep @var{material}: its name with each
## @qcode{"-"} as @qcode{"_"}.
## @end deftypefn
function f = repro_field (material)
  f = strrep (material, "-", "_");
endfunction
