## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {@var{def} =} __lafortune_model_def__ (@var{type})
## @deftypefnx {} {@var{types} =} __lafortune_model_def__ ()
## The definition of an analytic model type: the list of types, or the
## struct of @var{type}, each defined in its own file @code{brdf_TYPE.m}
## (Lafortune's in @code{brdf_lafortune.m}; a physically based type's file
## gives its lobe, and the rest is completed here).
##
## Every type has @code{type}, @code{title}, @code{fields} (the model
## struct's parameter fields, each NLOBES x 3 but @code{rho_d}, 1 x 3),
## @code{formula}, @code{reduce} (what the model sees of a pair of
## directions: the fit merges samples equal in it), and its files' layout,
## which brdf_export's one writer per format walks: @code{tag} (the JSON's
## format), @code{table} (the text table's head, a format of the name and
## the number of lobes, and the row names of the lobe fields) and
## @code{shader} (BRDF Explorer's head, lobe function, geometry, the lobe
## function's geometry arguments, the sliders' name format and their
## ranges [lo, hi, cap] per lobe field), and for the one fit driver
## (fit_driver) @code{coords} (the fit's coordinates, a function of a verb:
## fit_lafortune, fit_phys), @code{blank} (the lobe fields of a lobe not
## fitted) and @code{grow} (the fit's policy: @code{below}, samples below
## the horizon enter the fit; @code{screen}, starts are screened on a coarse
## grid; @code{first}, the first accepted start ends a lobe's search, else
## the best of all is kept; @code{albedo}, the fit reports it).  A physically based
## type (@code{def.lobe}: [g, dg] = lobe (X, q), of unit amplitude) also
## has @code{shape} (its shape parameters' names), @code{lo}, @code{hi}
## (bounds of [ks, shape]), @code{scale} ("log" or "lin" per shape
## parameter: how the fit moves it), @code{starts} (candidate values per
## shape parameter), @code{width} (the lobe's angular width in radians,
## for quadrature) and @code{glsl} (the lobe in GLSL, from ch, cd, t2, s5,
## hh, ci, co and its parameters, for BRDF Explorer).
## @end deftypefn

function def = __lafortune_model_def__ (type)
  persistent defs = struct ();
  TYPES = {"lafortune", "blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"};
  if (nargin == 0)
    def = TYPES;
    return;
  endif
  if (! ischar (type) || ! any (strcmp (type, TYPES)))
    error ("lafortune:badModelType", "unknown model type '%s'; expected one of %s",
           __lafortune_arg_str__ (type), strjoin (TYPES, ", "));
  endif
  if (isfield (defs, type))
    def = defs.(type);
    return;
  endif
  def = feval (["brdf_" type]);
  if (! isfield (def, "fields"))          # a physically based type: ks times a lobe
    def = physical (def);
  endif
  defs.(type) = def;
endfunction

## a physically based type's definition completed: its fields (ks and the
## shape), the reduction, its lobe, and its files' layout (see
## brdf_lafortune): the same for all of them but the names, the formula,
## the lobe's GLSL and the sliders' ranges (from the bounds and the starts)
function def = physical (def)
  type = def.type;
  def.fields = [{"rho_d", "ks"}, def.shape];
  def.formula = ["f = rho_d/pi + sum_k " def.formula];
  def.reduce = "(cos theta_i, cos theta_o, wi.wo)";
  def.lobe = str2func (["brdf_" type]);
  def.coords = @fit_phys;
  ## a lobe not fitted (ks 0, the shape at its lower bounds), and the fit's
  ## policy (fit_driver, fit_grow): samples on or below the horizon, where
  ## every such model is 0, are left out; every start of a lobe is run and
  ## the best kept; the albedo is reported
  def.blank = [0, def.lo(2:end)];
  def.grow = struct ("below", false, "screen", false, "first", false, "albedo", true);
  def.tag = "brdf-model";
  pc = @(s) strrep (s, "%", "%%");        # text put into a format
  def.table = struct ("head", [sprintf("# %s model (type %s): ", pc (def.title), type) ...
                               "%s, %d lobe(s), one column per channel\n" ...
                               "# " pc(def.formula) "\n" ...
                               "# ci, co = cos theta_i, cos theta_o; ch = cos theta_h; cd = cos theta_d\n"],
                      "labels", {def.fields(2:end)});
  geo = {"ci", "co", "hh", "ch", "t2", "cd", "s5"};
  args = strjoin (strcat ({"float "}, [{"ks"}, def.shape, geo]), ", ");
  ## sliders: ks from 0 to 1 or twice its value; a shape parameter from its
  ## lower bound to twice its value, at least to the largest start of the
  ## fit (1000 at most), never beyond its upper bound
  top = cellfun (@(s) min (max (s), 1000), def.starts);
  slider = [0 1 NaN; def.lo(2:end)(:), top(:), def.hi(2:end)(:)];
  def.shader = struct ("head", [sprintf("# %s model '", pc (def.title)) "%s" ...
                                sprintf("' (type %s), ", type) ...
                                "%d lobe(s), exported by lafortune_export\n" ...
                                "# " pc(def.formula) ", per channel\n" ...
                                "# ci, co: cos theta_i, cos theta_o; hh = |L+V|^2; ch = cos theta_h; t2 = tan^2 theta_h;\n" ...
                                "# cd = cos theta_d = L.H; s5 = (1 - cd)^5\n\n"],
                       "lobe", ["// one lobe of one channel: ks times the lobe of unit amplitude\n" ...
                                "float lobe(" args ")\n{\n" def.glsl "    return ks * g;\n}\n\n"],
                       "geometry", ["    float ci = dot(L, N);\n" ...
                                    "    float co = dot(V, N);\n" ...
                                    "    if (ci <= 0.0 || co <= 0.0) return vec3(0.0);   // below the horizon, as material_eval\n" ...
                                    "    float hh = max(2.0 + 2.0 * dot(L, V), 1.0e-30);   // |L + V|^2\n" ...
                                    "    float s = ci + co;\n" ...
                                    "    float ch = s / sqrt(hh);\n" ...
                                    "    float t2 = max(hh - s * s, 0.0) / (s * s);\n" ...
                                    "    float cd = min(sqrt(hh) / 2.0, 1.0);\n" ...
                                    "    float s5 = pow(1.0 - cd, 5.0);\n"],
                       "args", {geo}, "name", "%s_%d_%s", "slider", slider);
endfunction
