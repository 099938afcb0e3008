## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} repro_method (@var{name})
## @deftypefnx {} {@var{names} =} repro_method (@var{methods}, @var{models})
## The one reading of a fit method's name in `make reproduce` and `make
## database`.  A method is a table, optionally the colour mode of its fit,
## optionally the model type it fits, joined by underscores:
## TABLE[_COLOR][_MODEL], as @code{scene}, @code{scene_shared},
## @code{scene_ggx}, @code{inplane_shared_cooktorrance}.  Without a model
## the method fits the Lafortune model (the paper's), so the Lafortune
## methods keep their names and files.
##
## @var{p} has @code{name}, @code{table} (@code{inplane},
## @code{hemisphere}, @code{scene}: see repro_table), @code{color}
## (@code{shared}, @code{separate}, or empty: the fit's default),
## @code{model} (the type for brdf_fit; @code{lafortune} when the name has
## none), @code{weight} (the fit's weighting, empty for the table's
## default: a @code{hemisphere} method fits plain solid-angle weights,
## @code{general} the weighting its views choose), @code{base} (the name without its model: the method whose table
## and options it fits, and the key of the errors on that table in the fit
## record), @code{opts} (the fit's options for the colour mode) and
## @code{label}, the method's name in the reports and figures (the three
## tables of the paper's model by what they are, as @qcode{"in-plane (the
## paper's method)"}; any other as table, colour mode and model, as
## @qcode{"scene, shared colour, ggx"}).  The model is not checked here
## against the list of types: brdf_fit does it.
##
## With two cell arrays, the methods of the pipeline: every method of
## @var{methods} (METHODS) crossed with every model type of @var{models}
## (MODELS), the models in their order, each with the methods in theirs;
## a method that names its model already is taken once, as it is.
## @end deftypefn
function out = repro_method (name, models)
  if (nargin == 2)
    out = {};
    for t = models(:)'
      for m = name(:)'
        p = repro_method (m{1});
        if (! strcmp (p.base, p.name))
          q = p.name;                 # names its model: once, as it is
        elseif (strcmp (t{1}, "lafortune"))
          q = p.name;
        else
          q = [p.name "_" t{1}];
        endif
        if (! any (strcmp (out, q)))
          out{end+1} = q;
        endif
      endfor
    endfor
    return;
  endif
  if (! ischar (name) || isempty (name))
    error ("lafortune:badConfig", "repro_method: a method must be a name, got %s", class (name));
  endif
  parts = strsplit (name, "_");
  p = struct ("name", name, "table", parts{1}, "color", "", "model", "lafortune", "weight", "",
              "base", name, "opts", {{}});
  if (strcmp (p.table, "hemisphere"))
    p.weight = "plain";                 # the solid-angle baseline (0.6's method)
    p.opts = {"weight", "plain"};
  endif
  rest = parts(2:end);
  if (! isempty (rest) && any (strcmp (rest{1}, {"shared", "separate"})))
    p.color = rest{1};
    p.opts = [p.opts, {"color", rest{1}}];
    rest(1) = [];
  endif
  if (numel (rest) == 1 && ! isempty (rest{1}) && ! strcmp (rest{1}, "lafortune"))
    p.model = rest{1};
    p.base = name(1:end - numel (rest{1}) - 1);
  elseif (! isempty (rest))
    error ("lafortune:badConfig",
           ["repro_method: unknown method '%s': expected TABLE[_COLOR][_MODEL], a table " ...
            "(inplane, hemisphere, general, scene), optionally _shared or _separate, optionally a model " ...
            "type other than lafortune (a method without one fits the Lafortune model)"], name);
  endif
  p.label = method_label (p);
  out = p;
endfunction

function s = method_label (p)
  names = struct ("inplane", "in-plane", "hemisphere", "hemisphere", "scene", "scene",
                  "general", "general");
  notes = struct ("inplane", " (the paper's method)", "hemisphere", " (solid-angle weights)",
                  "scene", " (for the scene's light)", "general", " (recommended)");
  s = p.table;
  if (isfield (names, s))
    s = names.(s);
  endif
  if (isempty (p.color) && strcmp (p.model, "lafortune") && isfield (notes, p.table))
    s = [s notes.(p.table)];
    return;
  endif
  if (! isempty (p.color))
    s = [s ", " p.color " colour"];
  endif
  if (! strcmp (p.model, "lafortune"))
    s = [s ", " p.model];
  endif
endfunction
