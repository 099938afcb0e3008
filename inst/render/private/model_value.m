## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{f} =} model_value (@var{def}, @var{p}, @var{X})
## The value of a physically based model's channel at @var{X} (private):
## @code{model_core (def, p, X)}, computed by the oct-file
## @code{__model_core__} (the same operations, compiled, on all cores) when
## it is built, else by model_core itself.  For the renderers' shading
## (material_x); the fits call model_core, whose Octave code stays the
## reference.  An oct-file that does not load (built for another Octave)
## raises the warning @code{lafortune:noOctFile} once.
## @end deftypefn
function f = model_value (def, p, X)
  [done, f] = __lafortune_oct_call__ ("__model_core__", "model_value", def.type, p, X);
  if (! done)
    f = __lafortune_model_core__ (def, p, X);
  endif
endfunction
