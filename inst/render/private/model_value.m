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
  persistent broken = false;
  if (! broken && exist ("__model_core__", "file") == 3)
    try
      f = __model_core__ (def.type, p, X);
      return;
    catch err
      if (strncmp (err.identifier, "lafortune:", 10))
        rethrow (err);
      endif
      broken = true;
      warning ("lafortune:noOctFile",
               "model_value: the oct-file __model_core__ does not work (%s); using the Octave arithmetic (rebuild it: make -C src)",
               err.message);
    end_try_catch
  endif
  f = __lafortune_model_core__ (def, p, X);
endfunction
