## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} brdf_export (@var{model}, @var{file})
## @deftypefnx {lafortune} {} brdf_export (@var{model}, @var{file}, @var{format})
## Write an analytic model to a file: JSON, a text table, a BRDF Explorer
## shader or a MERL @file{.binary}.
##
## @var{model} is any analytic model (see @code{brdf_model}): a Lafortune
## model, a struct with fields @code{rho_d} (1 x 3), @code{Cxy}, @code{Cz},
## @code{e} (nlobes x 3), or a physically based one with a field
## @code{type} (@code{"blinnphong"}, @code{"ward"}, @code{"cooktorrance"},
## @code{"ggx"}, @code{"ashikhminshirley"}), @code{rho_d} and, per lobe,
## @code{ks} and the type's shape parameters (nlobes x 3).  Its optional
## @code{name} is written as one line (control characters become spaces;
## "lafortune-model", or "TYPE-model", when there is none).
##
## @var{format} is one of the following.  Left out, it is taken from the
## extension of @var{file} (in any case): @file{.json} "json", @file{.txt}
## "text", @file{.brdf} "brdfexplorer", @file{.binary} "merl"; any other
## extension is the error @code{lafortune:badFormat}.  A @var{format}
## given is used whatever the extension.
##
## @table @code
## @item "json"
## the parameters as JSON (@code{jsonencode}): format tag
## (@code{"lafortune-model"}; @code{"brdf-model"} with a field @code{type}
## for the other types), name, nlobes, the formula and the model's fields
## (@code{rho_d}, then lobes in rows, R, G, B in columns: Cxy, Cz, e, or
## ks and the shape parameters) and, under @code{exact}, the same values
## as IEEE-754 hex strings so that @code{brdf_import} gives back the
## very same doubles.
## @item "text"
## a readable table: a header naming the model's type and formula, rows
## rho_d and, per lobe, each parameter (Lafortune: o_xy, o_z and n, the
## paper's layout); columns R, G, B.
## @item "brdfexplorer"
## an analytic @file{.brdf} file for Disney's BRDF Explorer: every
## parameter of every channel is a slider, the shader evaluates the same
## model, 0 below the horizon.  Lafortune: ux vx + uy vy as dot(L,V) -
## dot(L,N) dot(V,N), free of the tangents X and Y (which BRDF Explorer's
## lit sphere leaves undefined where the normal is +-Y).  The other types:
## a GLSL function @code{lobe} (the type's lobe times ks) from cos theta_i,
## cos theta_o, |L+V|^2, cos theta_h, tan^2 theta_h, cos theta_d and (1 -
## cos theta_d)^5, which the shader computes from L, V and N alone.
## @item "merl"
## the model resampled into a MERL @file{.binary} (see @code{merl_synth},
## @code{merl_write}).
## @end table
##
## The output goes to a temporary file in the same folder, which is then
## renamed: a failed or interrupted export leaves any earlier @var{file}
## untouched and no half file.
##
## @example
## @group
## m = struct ("name", "demo", "rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1], ...
##             "Cz", [0.9 0.9 0.9], "e", [30 30 30]);
## brdf_export (m, "demo.json");           # format from the extension
## brdf_export (m, "demo.txt", "text");
## type demo.txt
## g = brdf_model ("ggx", "rho_d", [0.1 0.05 0.02], "ks", 1, ...
##                 "alpha", 0.2, "F0", 0.04, "name", "gloss");
## brdf_export (g, "gloss.json");
## brdf_export (g, "gloss.brdf");          # for BRDF Explorer
## g2 = brdf_import ("gloss.json");        # the very same doubles
## @end group
## @end example
## @seealso{brdf_import, brdf_model, material_eval, lafortune_fit, merl_write}
## @end deftypefn
function brdf_export (model, file, format)
  if (nargin < 2 || nargin > 3)
    print_usage ();
  endif
  [model, def] = __lafortune_check_model__ (model, "brdf_export");
  __lafortune_check_bounded__ (model, "brdf_export");
  name = [def.type "-model"];
  if (isfield (model, "name") && ischar (model.name) && ! isempty (model.name))
    ## one line of printable text: a control character (a newline) would end
    ## the comment it is written in, and BRDF Explorer refuses such a file
    nm = model.name(:).';
    nm(nm < 32 | nm == 127) = " ";
    nm = strtrim (nm);
    if (! isempty (nm))
      name = nm;
    endif
  endif
  formats = {"json", "text", "brdfexplorer", "merl"};
  if (nargin < 3)
    format = format_of (file, formats);
  endif
  if (! ischar (format) || ! any (strcmpi (format, formats)))
    error ("lafortune:badFormat", "brdf_export: unknown FORMAT '%s'; expected one of %s",
           __lafortune_arg_str__ (format), strjoin (formats, ", "));
  endif
  format = lower (format);
  if (strcmp (format, "merl"))
    merl_write (file, merl_synth (model, "name", name));
    return;
  endif
  switch (format)
    case "json"
      txt = json_text (model, def, name);
    case "text"
      txt = table_text (model, def, name);
    case "brdfexplorer"
      txt = shader_text (model, def, name);
  endswitch
  __lafortune_write__ (file, "brdf_export", "text", txt);
endfunction

## the format of FILE's extension
function format = format_of (file, formats)
  exts = {".json", ".txt", ".brdf", ".binary"};
  if (! ischar (file) || isempty (file) || rows (file) != 1)
    error ("lafortune:badFile", "brdf_export: FILE must be a non-empty string");
  endif
  [~, ~, ext] = fileparts (file);
  k = find (strcmpi (ext, exts), 1);
  if (isempty (k))
    known = strjoin (cellfun (@(e, f) sprintf ("%s (%s)", e, f), exts, formats,
                              "UniformOutput", false), ", ");
    if (isempty (ext))
      what = "has no extension";
    else
      what = sprintf ("has the unknown extension '%s'", ext);
    endif
    error ("lafortune:badFormat",
           "brdf_export: FILE '%s' %s; give FORMAT or use a known extension: %s",
           file, what, known);
  endif
  format = formats{k};
endfunction

## The writers walk the type's definition (model_def): its fields, its
## format tag, its table's row names and its shader's parts.

## the JSON of a model: its format tag (and type, for "brdf-model"), and its
## fields in def.fields order, readable and as exact hex strings
function txt = json_text (m, def, name)
  s = struct ("format", def.tag, "version", 1);
  if (strcmp (def.tag, "brdf-model"))
    s.type = def.type;
  endif
  s.name = name;
  s.nlobes = rows (m.(def.fields{2}));
  s.formula = [def.formula ", per channel R, G, B"];
  ex = struct ();
  for f = def.fields
    s.(f{1}) = m.(f{1});
    ex.(f{1}) = hex_of (m.(f{1}));
  endfor
  s.exact = ex;
  txt = [jsonencode(s) "\n"];
endfunction

## the values of V row after row (lobe after lobe, R, G, B) as IEEE-754 hex
## strings; none for no lobes
function h = hex_of (v)
  h = {};
  if (! isempty (v))
    v = v.';
    h = cellstr (num2hex (v(:))).';
  endif
endfunction

## a readable table: the type's head, then rho_d and each lobe's parameters
## under the table's names, one column per channel
function txt = table_text (m, def, name)
  n = rows (m.(def.fields{2}));
  row = @(label, v) sprintf ("%-14s %14.6g %14.6g %14.6g\n", label, v);
  txt = [sprintf(def.table.head, name, n) ...
         sprintf("%-14s %14s %14s %14s\n", "parameter", "R", "G", "B") row("rho_d", m.rho_d)];
  for k = 1:n
    for j = 1:numel (def.table.labels)
      txt = [txt row(sprintf ("lobe %d %s", k, def.table.labels{j}), m.(def.fields{j+1})(k,:))];
    endfor
  endfor
endfunction

## BRDF Explorer's shader: a slider for every parameter of every channel, the
## type's lobe function called per lobe and channel with its parameters and
## the geometry's arguments, which BRDF computes from L, V and N alone
function txt = shader_text (m, def, name)
  sh = def.shader;
  n = rows (m.(def.fields{2}));
  ch = "rgb";
  lob = def.fields(2:end);
  par = [slider("rho_d_r", [0 1 NaN], m.rho_d(1)) slider("rho_d_g", [0 1 NaN], m.rho_d(2)) ...
         slider("rho_d_b", [0 1 NaN], m.rho_d(3))];
  body = "    vec3 f = vec3(rho_d_r, rho_d_g, rho_d_b) / PI;\n";
  for k = 1:n
    calls = cell (1, 3);
    for c = 1:3
      nm = cell (1, numel (lob));
      for j = 1:numel (lob)
        nm{j} = sprintf (sh.name, lob{j}, k, ch(c));
        par = [par slider(nm{j}, sh.slider(j,:), m.(lob{j})(k,c))];
      endfor
      calls{c} = sprintf ("lobe(%s, %s)", strjoin (nm, ", "), strjoin (sh.args, ", "));
    endfor
    body = [body "    f += vec3(" strjoin(calls, ",\n              ") ");\n"];
  endfor
  txt = ["analytic\n\n" sprintf(sh.head, name, n) ...
         "::begin parameters\n" par "::end parameters\n\n" ...
         "::begin shader\n\n" ...
         "const float PI = 3.14159265358979323846;\n\n" ...
         sh.lobe ...
         "vec3 BRDF( vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y )\n{\n" ...
         sh.geometry ...
         body ...
         "    return f;\n}\n\n" ...
         "::end shader\n"];
endfunction

## a slider for value V over R = [lo, hi, cap]: with no cap (NaN) from lo to
## hi, widened to hold V and twice V; with a cap (a bound of the parameter)
## from lo to hi or twice V, never beyond the cap
function s = slider (nm, r, v)
  if (isnan (r(3)))
    lo = min (r(1), floor (v));
    hi = max (r(2), ceil (2 * v));
  else
    lo = r(1);
    hi = min (r(3), max (r(2), 2 * v));
  endif
  s = sprintf ("float %s %.9g %.9g %.17g\n", nm, lo, hi, v);
endfunction

%!shared m, d
%! m = struct ("name", "test model", "rho_d", [0.1 0.05 pi/100], "Cxy", [-1 -1.1 -0.9; 0.3 0.4 0.5], ...
%!             "Cz", [0.9 0.95 0.85; 0.3 0.2 0.1], "e", [30.123456789 40 1234.5; 2 3 4]);
%! d = tempname (); mkdir (d);

%!test
%! f = fullfile (d, "m.json");
%! brdf_export (m, f, "json");
%! r = brdf_import (f);
%! assert (r.name, "test model");
%! for fld = {"rho_d", "Cxy", "Cz", "e"}
%!   assert (isequal (r.(fld{1}), m.(fld{1})));   # bit for bit
%! endfor

%!test
%! f = fullfile (d, "m.txt");
%! brdf_export (m, f, "text");
%! t = fileread (f);
%! assert (! isempty (strfind (t, "lobe 2 o_xy")));
%! assert (! isempty (regexp (t, "rho_d\\s+0.1\\s+0.05\\s+0.0314159")));
%! assert (! isempty (regexp (t, "lobe 1 n\\s+30.1235\\s+40\\s+1234.5")));

%!test
%! f = fullfile (d, "m.brdf");
%! brdf_export (m, f, "brdfexplorer");
%! t = fileread (f);
%! assert (strncmp (t, "analytic", 8));
%! assert (! isempty (strfind (t, "::begin parameters")));
%! assert (! isempty (strfind (t, "vec3 BRDF( vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y )")));
%! assert (! isempty (regexp (t, "float e1_b 0 2469 1234.5")));
%! assert (numel (regexp (t, "\\nfloat \\w+ [-0-9]")), 3 + 2 * 9);
%! ## below the horizon 0, as lafortune_eval; ux vx + uy vy free of X and Y
%! assert (! isempty (strfind (t, "if (ln <= 0.0 || vn <= 0.0) return vec3(0.0);")));
%! assert (! isempty (strfind (t, "float sxy = dot(L, V) - ln * vn;")));
%! assert (isempty (regexp (t, "dot\\([LV], [XY]\\)", "once")));
%! assert (! isempty (strfind (t, "Lafortune model 'test model'")));

%!test
%! ## the shader's formula, evaluated here, is lafortune_eval's (1e-12),
%! ## for pairs above and below the horizon and a single pair
%! t = [0.2 0.7 1.2 1.5]; p = [0 0.5 2 3];
%! [T, P] = ndgrid (t, p);
%! L = [sin(T(:)) .* cos(P(:)) sin(T(:)) .* sin(P(:)) cos(T(:))];
%! V = L([3 1 4 2 8 5 6 7 10 9 12 11 14 13 16 15],:);
%! V(end,:) = [0 sin(2) cos(2)];                     # one below the horizon
%! ln = L(:,3); vn = V(:,3);
%! sxy = sum (L .* V, 2) - ln .* vn; sz = ln .* vn;
%! g = repmat (m.rho_d / pi, rows (L), 1);
%! for k = 1:2
%!   g += max (m.Cxy(k,:) .* sxy + m.Cz(k,:) .* sz, 0) .^ m.e(k,:);
%! endfor
%! g(ln <= 0 | vn <= 0,:) = 0;
%! assert (g, lafortune_eval (m, L, V), 1e-12);
%! assert (lafortune_eval (m, L(1,:), V(end,:)), [0 0 0]);

%!test
%! ## control characters leave the name; a model without a name says so
%! f = fullfile (d, "n.brdf");
%! m2 = m; m2.name = sprintf ("red\nplastic\t(2 lobes)\r");
%! brdf_export (m2, f, "brdfexplorer");
%! t = fileread (f);
%! assert (! isempty (strfind (t, "Lafortune model 'red plastic (2 lobes)'")));
%! assert (! any (t < 32 & t != 10));
%! brdf_export (m2, fullfile (d, "n.txt"), "text");
%! t = fileread (fullfile (d, "n.txt"));
%! assert (strncmp (t, "# Lafortune model: red plastic (2 lobes), 2 lobe(s)", 50));
%! brdf_export (rmfield (m, "name"), f, "brdfexplorer");
%! assert (! isempty (strfind (fileread (f), "Lafortune model 'lafortune-model'")));

%!test
%! f = fullfile (d, "m.binary");
%! brdf_export (m, f, "merl");
%! b = merl_read (f);
%! wi = [sind(30) 0 cosd(30)]; wo = [-sind(20) 0 cosd(20)];
%! assert (merl_eval (b, wi, wo), lafortune_eval (m, wi, wo), -0.05);

%!test
%! ## an export whose write fails (a file size limit of 0 makes the disk
%! ## refuse) keeps the earlier file and leaves no temporary
%! f = fullfile (d, "keep.json");
%! brdf_export (m, f, "json");
%! before = fileread (f);
%! scr = fullfile (d, "w.m");
%! fid = fopen (scr, "w");
%! fprintf (fid, "addpath ('%s');\n", fileparts (which ("__lafortune_write__")));
%! fprintf (fid, "m = struct ('rho_d', [1 1 1], 'Cxy', [1 1 1], 'Cz', [1 1 1], 'e', [2 2 2]);\n");
%! fprintf (fid, "try\n brdf_export (m, '%s', 'json');\n exit (3);\ncatch err\n disp (err.identifier);\nend_try_catch\n", f);
%! fclose (fid);
%! [st, out] = system (sprintf ("bash -c \"trap '' XFSZ; ulimit -f 0; octave-cli --no-gui --norc --no-history '%s'\" 2>&1", scr));
%! assert (st == 0, "%s", out);
%! assert (! isempty (strfind (out, "lafortune:unwritable")), out);
%! assert (fileread (f), before);
%! unlink (scr);
%! assert (isempty (dir (fullfile (d, ".keep*"))));

%!error <Invalid call> brdf_export (m)
%!error <Invalid call> brdf_export ()
%!error <unknown FORMAT 'yaml'> brdf_export (m, "x.yaml", "yaml")
%!error id=lafortune:unboundedModel brdf_export (struct ("rho_d", [0 0 0], "Cxy", [-1.5 0 0], "Cz", [0.9 0 0], "e", [738 1 1]), "x.json")
%!error id=lafortune:badFormat brdf_export (m, "x.json", 3)
%!error id=lafortune:unwritable brdf_export (m, "/nonexistent-dir/x.json", "json")
%!error id=lafortune:badModel brdf_export (struct ("rho_d", 1), "x.json", "json")

%!function m = two_lobes (t)
%!  ## a model of type T with two lobes, each channel its own values
%!  if (strcmp (t, "lafortune"))
%!    m = brdf_model (t, "rho_d", [0.1 0.05 pi/100], "Cxy", [-1 -1.1 -0.9; 0.3 0.4 0.5], ...
%!                    "Cz", [0.9 0.95 0.85; 0.3 0.2 0.1], "e", [30.123456789 40 1234.5; 2 3 4]);
%!  else
%!    d = brdf_model (t);
%!    m = brdf_model (t, "rho_d", [0.1 0.05 pi/100], "ks", [0.5 0.7 0.9; 0.2 0.3 0.1] * pi / 3);
%!    for s = d.shape
%!      switch (s{1})
%!        case "n"
%!          m.n = [30.123456789 40 1234.5; 2 3 4.5];
%!        case "F0"
%!          m.F0 = [0.04 0.05 0.9; 1/3 0.5 1];
%!        otherwise                                   # alpha, m
%!          m.(s{1}) = [0.1 0.2 pi/10; 0.45 0.5 0.6];
%!      endswitch
%!    endfor
%!  endif
%!  m.name = sprintf ("two %s lobes", t);
%!endfunction

%!function r = glsl_lobe (code_, names_, vals_)
%!  ## the body of the .brdf file's GLSL function lobe, run here: its
%!  ## arguments NAMES_ set to VALS_ (scalars), GLSL's pow and PI
%!  PI = pi;
%!  pow = @(a, b) a ^ b;
%!  for j_ = 1:numel (names_)
%!    eval (sprintf ("%s = vals_(%d);", names_{j_}, j_));
%!  endfor
%!  r = [];
%!  eval (code_);
%!endfunction

%!function f = shader_eval (t, L, V)
%!  ## the shader of .brdf text T (a type other than Lafortune) at the pairs
%!  ## L, V: the sliders' values, the angles as the shader's BRDF computes
%!  ## them (re-implemented here), and the file's own lobe function and its
%!  ## calls, lobe by lobe and channel by channel, read from the text
%!  par = regexp (t, "\\nfloat (\\w+) \\S+ \\S+ (\\S+)", "tokens");
%!  val = struct ();
%!  for k = 1:numel (par)
%!    val.(par{k}{1}) = str2double (par{k}{2});
%!  endfor
%!  lob = regexp (t, "\\nfloat lobe\\(([^)]*)\\)\\n\\{\\n(.*?)\\n\\}\\n", "tokens", "once");
%!  args = regexp (lob{1}, "float (\\w+)", "tokens");
%!  args = [args{:}];
%!  code = strrep (regexprep (lob{2}, "\\<float ", ""), "return ", "r = ");
%!  code = strrep (code, "\n", " ");
%!  calls = regexp (t, "f \\+= vec3\\(lobe\\(([^)]*)\\),\\s*lobe\\(([^)]*)\\),\\s*lobe\\(([^)]*)\\)\\);", "tokens");
%!  ci = L(:,3);
%!  co = V(:,3);
%!  hh = max (2 + 2 * sum (L .* V, 2), 1e-30);
%!  s = ci + co;
%!  ch = s ./ sqrt (hh);
%!  t2 = max (hh - s .* s, 0) ./ (s .* s);
%!  cd = min (sqrt (hh) / 2, 1);
%!  s5 = (1 - cd) .^ 5;
%!  f = repmat ([val.rho_d_r, val.rho_d_g, val.rho_d_b] / pi, rows (L), 1);
%!  for i = find (ci > 0 & co > 0).'
%!    geo = struct ("ci", ci(i), "co", co(i), "hh", hh(i), "ch", ch(i), "t2", t2(i), ...
%!                  "cd", cd(i), "s5", s5(i));
%!    for k = 1:numel (calls)
%!      for c = 1:3
%!        a = strtrim (strsplit (calls{k}{c}, ","));
%!        x = zeros (1, numel (a));
%!        for j = 1:numel (a)
%!          if (isfield (geo, a{j}))
%!            x(j) = geo.(a{j});
%!          else
%!            x(j) = val.(a{j});
%!          endif
%!        endfor
%!        f(i,c) += glsl_lobe (code, args, x);
%!      endfor
%!    endfor
%!  endfor
%!  f(ci <= 0 | co <= 0, :) = 0;
%!endfunction

%!test
%! ## JSON of every type: its type and formula, and back through
%! ## brdf_import bit for bit
%! for t = brdf_model ()
%!   mt = two_lobes (t{1});
%!   def = brdf_model (t{1});
%!   f = fullfile (d, [t{1} ".json"]);
%!   brdf_export (mt, f, "json");
%!   r = brdf_import (f);
%!   assert (r.name, mt.name);
%!   for fld = def.fields
%!     assert (size (r.(fld{1})), size (mt.(fld{1})));
%!     assert (isequal (typecast (r.(fld{1})(:), "uint64"), typecast (mt.(fld{1})(:), "uint64")),
%!             "%s.%s", t{1}, fld{1});
%!   endfor
%!   s = jsondecode (fileread (f));
%!   if (strcmp (t{1}, "lafortune"))
%!     assert (s.format, "lafortune-model");
%!     assert (! isfield (r, "type") && ! isfield (s, "type"));
%!   else
%!     assert (s.format, "brdf-model");
%!     assert (s.type, t{1});
%!     assert (r.type, t{1});
%!     assert (isequal (r, mt));
%!     assert (s.formula, [def.formula ", per channel R, G, B"]);
%!     assert (fieldnames (s.exact), def.fields(:));
%!     assert (s.nlobes, 2);
%!     assert (s.(def.shape{1}), mt.(def.shape{1}), 1e-15);   # readable too
%!   endif
%! endfor

%!test
%! ## one lobe and none round-trip too
%! g = two_lobes ("cooktorrance");
%! f = fullfile (d, "one.json");
%! for n = {1, []}
%!   h = g;
%!   for fld = {"ks", "m", "F0"}
%!     h.(fld{1}) = h.(fld{1})(n{:},:);
%!   endfor
%!   brdf_export (h, f);
%!   assert (isequal (brdf_import (f), h));
%! endfor

%!test
%! ## text of every type: a header with its title and formula, a row per
%! ## parameter, columns R, G, B
%! for t = brdf_model ()(2:end)
%!   mt = two_lobes (t{1});
%!   def = brdf_model (t{1});
%!   f = fullfile (d, [t{1} ".txt"]);
%!   brdf_export (mt, f, "text");
%!   x = fileread (f);
%!   h = sprintf ("# %s model (type %s): two %s lobes, 2 lobe(s), one column per channel\n",
%!                def.title, t{1}, t{1});
%!   assert (strncmp (x, h, numel (h)));
%!   assert (! isempty (strfind (x, ["\n# " def.formula "\n"])));
%!   assert (! isempty (regexp (x, "\\nrho_d\\s+0.1\\s+0.05\\s+0.0314159\\n")));
%!   assert (! isempty (regexp (x, "\\nlobe 1 ks\\s+0.523599\\s+0.733038\\s+0.942478\\n")));
%!   for k = 1:2
%!     for fld = def.fields(2:end)
%!       row = sprintf ("\n%-14s %14.6g %14.6g %14.6g\n", sprintf ("lobe %d %s", k, fld{1}), mt.(fld{1})(k,:));
%!       assert (! isempty (strfind (x, row)), row);
%!     endfor
%!   endfor
%!   assert (numel (strsplit (strtrim (x), "\n")), 5 + 2 * numel (def.shape) + 2);
%! endfor
%! x = fileread (fullfile (d, "ggx.txt"));
%! assert (! isempty (regexp (x, "\\nlobe 1 alpha\\s+0.1\\s+0.2\\s+0.314159\\n")));
%! assert (! isempty (regexp (x, "\\nlobe 2 F0\\s+0.333333\\s+0.5\\s+1\\n")));

%!test
%! ## BRDF Explorer file of every type: the type's GLSL, a slider per
%! ## parameter and channel within the type's bounds, and the shader
%! ## evaluated here is material_eval (1e-12 relative), on pairs above and
%! ## below the horizon, at and near the mirror direction
%! t = [0.2 0.7 1.2 1.5]; p = [0 0.5 2 3];
%! [T, P] = ndgrid (t, p);
%! L = [sin(T(:)) .* cos(P(:)) sin(T(:)) .* sin(P(:)) cos(T(:))];
%! V = L([3 1 4 2 8 5 6 7 10 9 12 11 14 13 16 15],:);
%! R = [-L(:,1) -L(:,2) L(:,3)];                     # mirror directions
%! Q = R + 0.05 * [0.3 -0.2 0.1];
%! Q ./= sqrt (sum (Q .^ 2, 2));                     # near them
%! L = [L; L; L; 0 0 1; 0.6 0 -0.8];
%! V = [V; R; Q; 0 sin(2) cos(2); 0 0 1];            # the last two below the horizon
%! below = L(:,3) <= 0 | V(:,3) <= 0;
%! ch = "rgb";
%! for ty = brdf_model ()(2:end)
%!   mt = two_lobes (ty{1});
%!   def = brdf_model (ty{1});
%!   f = fullfile (d, [ty{1} ".brdf"]);
%!   brdf_export (mt, f, "brdfexplorer");
%!   x = fileread (f);
%!   assert (strncmp (x, "analytic\n", 9));
%!   assert (! isempty (strfind (x, sprintf ("# %s model 'two %s lobes' (type %s), 2 lobe(s)",
%!                                           def.title, ty{1}, ty{1}))));
%!   assert (! isempty (strfind (x, def.glsl)));
%!   assert (! isempty (strfind (x, ["{\n" def.glsl "    return ks * g;\n}\n"])));
%!   assert (! isempty (strfind (x, sprintf ("float lobe(float ks, %s, float ci, float co, float hh, float ch, float t2, float cd, float s5)",
%!                                           strjoin (strcat ({"float "}, def.shape), ", ")))));
%!   assert (! isempty (strfind (x, "vec3 BRDF( vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y )")));
%!   for line = {"    float ci = dot(L, N);\n    float co = dot(V, N);\n", ...
%!               "    if (ci <= 0.0 || co <= 0.0) return vec3(0.0);", ...
%!               "    float hh = max(2.0 + 2.0 * dot(L, V), 1.0e-30);", ...
%!               "    float s = ci + co;\n    float ch = s / sqrt(hh);\n", ...
%!               "    float t2 = max(hh - s * s, 0.0) / (s * s);\n", ...
%!               "    float cd = min(sqrt(hh) / 2.0, 1.0);\n", ...
%!               "    float s5 = pow(1.0 - cd, 5.0);\n", ...
%!               "    vec3 f = vec3(rho_d_r, rho_d_g, rho_d_b) / PI;\n"}
%!     assert (! isempty (strfind (x, line{1})), line{1});
%!   endfor
%!   assert (isempty (regexp (x, "dot\\([LV], [XY]\\)", "once")));
%!   ## the sliders: one per parameter and channel, the model's very values
%!   sl = regexp (x, "(?<=\\n)float (\\w+) (\\S+) (\\S+) (\\S+)(?=\\n)", "tokens");
%!   assert (numel (sl), 3 + 2 * 3 * (numel (def.fields) - 1));
%!   names = cellfun (@(c) c{1}, sl, "UniformOutput", false);
%!   for c = 1:3
%!     want = {sprintf("rho_d_%s", ch(c)), mt.rho_d(c), 0, Inf};
%!     for k = 1:2
%!       for j = 2:numel (def.fields)
%!         want(end+1,:) = {sprintf("%s_%d_%s", def.fields{j}, k, ch(c)), mt.(def.fields{j})(k,c), ...
%!                          def.lo(j-1), def.hi(j-1)};
%!       endfor
%!     endfor
%!     for i = 1:rows (want)
%!       s = find (strcmp (names, want{i,1}));
%!       assert (numel (s), 1, want{i,1});
%!       v = str2double (sl{s}(2:4));
%!       assert (v(3), want{i,2});                     # exactly
%!       assert (want{i,3} <= v(1) && v(1) <= v(3) && v(3) <= v(2) && v(2) <= want{i,4}, want{i,1});
%!     endfor
%!   endfor
%!   ## the shader's formula, evaluated here, is material_eval's
%!   g = shader_eval (x, L, V);
%!   e = material_eval (mt, L, V);
%!   assert (all (e(below,:)(:) == 0) && all (g(below,:)(:) == 0));
%!   assert (all (e(! below,:)(:) > 0));
%!   err = max (abs (g(:) - e(:)) ./ max (abs (e(:)), realmin));
%!   assert (err <= 1e-12, "%s: relative error %g", ty{1}, err);
%!   assert (max (e(:)) > 10 * max (mt.rho_d) / pi);   # the lobes count
%! endfor

%!test
%! ## the format from the extension (any case), as with the format given
%! g = two_lobes ("ggx");
%! for e = {".json", "json"; ".txt", "text"; ".brdf", "brdfexplorer"; ".JSON", "json"}.'
%!   for mdl = {m, g}
%!     f1 = fullfile (d, ["ext" e{1}]);
%!     f2 = fullfile (d, ["fmt" e{1}]);
%!     brdf_export (mdl{1}, f1);
%!     brdf_export (mdl{1}, f2, e{2});
%!     assert (fileread (f1), fileread (f2));
%!   endfor
%! endfor
%! ## the format given wins over the extension
%! f = fullfile (d, "table.json");
%! brdf_export (g, f, "text");
%! assert (strncmp (fileread (f), "# GGX", 5));
%! ## a new user's first try: a Lafortune model to .json and back
%! f = fullfile (d, "gmp.json");
%! brdf_export (m, f);
%! r = brdf_import (f);
%! assert (isequal (r.e, m.e));

%!test
%! ## a GGX model resampled into MERL (from the extension .binary)
%! g = brdf_model ("ggx", "rho_d", [0.2 0.1 0.05], "ks", [1 0.8 0.6], "alpha", 0.3, "F0", 0.04,
%!                 "name", "ggx test");
%! f = fullfile (d, "g.binary");
%! brdf_export (g, f);
%! b = merl_read (f);
%! wi = [sind(30) 0 cosd(30); sind(45) 0 cosd(45)];
%! wo = [-sind(20) 0 cosd(20); -sind(45) 0 cosd(45)];
%! assert (merl_eval (b, wi, wo), material_eval (g, wi, wo), -0.05);
%! unlink (f);

%!error <unknown extension '.yaml'; give FORMAT or use a known extension: .json \(json\), .txt \(text\), .brdf \(brdfexplorer\), .binary \(merl\)> brdf_export (m, "x.yaml")
%!error id=lafortune:badFormat brdf_export (brdf_model ("ggx", "ks", 1), "x.brdfx")
%!error <has no extension> brdf_export (m, "gmp")
%!error id=lafortune:badFile brdf_export (m, 42)
%!error id=lafortune:badModelType brdf_export (struct ("type", "phong"), "x.json")
%!error id=lafortune:badModel brdf_export (struct ("type", "ggx", "rho_d", [0 0 0], "ks", 1, "alpha", 0.1, "F0", 0), "x.json")

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
