## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{txt} =} report_fill (@var{name}, @var{V})
## The text of the report template @file{scripts/templates/@var{name}.md}
## (or of the file @var{name}, a path with its folder) filled from the
## struct @var{V} (a report's summary, or a view of it).
## The template is Markdown with tags in double braces, a subset of
## Mustache's:
##
## @table @code
## @item @{@{x@}@}, @{@{x|FMT@}@}
## the value of field @code{x} (or a path @code{x.y}) of the innermost
## scope that has it: text as it is; a list of texts joined by ", "; a
## number or array each element by FMT (default @code{%g}), joined by " / ",
## NaN and empty as "-"; true and false as "yes" and "no" (joined by " / ").  @code{@{@{.@}@}}
## is the current item of a list of texts.
## @item @{@{#x@}@} @dots{} @{@{/x@}@}
## the block once for each element of a struct array or cell @code{x}, with
## the element's fields as the innermost scope; once for a true, nonzero or
## non-empty value of another kind; not at all for a missing, empty, false
## or zero one.
## @item @{@{^x@}@} @dots{} @{@{/x@}@}
## the block once when @code{x} is missing, empty, false or zero.
## @item @{@{>x@}@}
## the template @file{x.md} of the same folder, filled in the same scope.
## @end table
##
## A line that holds nothing but one section tag is left out with its end
## of line, so that blocks can stand on lines of their own between the rows
## of a table.  A missing field is an error (@code{lafortune:badTemplate}).
## @end deftypefn
function txt = report_fill (name, V)
  if (nargin != 2 || ! ischar (name) || ! isstruct (V))
    print_usage ();
  endif
  d = fullfile (fileparts (mfilename ("fullpath")), "templates");
  if (any (name == "/"))
    [d, name] = fileparts (name);
  endif
  txt = fill (read_template (d, name), {V}, d);
endfunction

function s = read_template (d, name)
  f = fullfile (d, [name ".md"]);
  if (! exist (f, "file"))
    error ("lafortune:badTemplate", "report_fill: no template %s: expected a file %s", name, f);
  endif
  s = fileread (f);
  ## a section tag alone on its line takes the line with it
  s = regexprep (s, '^[ \t]*(\{\{[#^/][^}]*\}\})[ \t]*\n', "$1", "lineanchors");
endfunction

function out = fill (s, scopes, d)
  out = "";
  pat = '\{\{([#^/>]?)\s*([^}|\s]+)\s*(\|[^}]*)?\}\}';
  while (true)
    [tok, b, e] = regexp (s, pat, "tokens", "start", "end", "once");
    if (isempty (tok))
      out = [out s];
      return;
    endif
    out = [out s(1:b-1)];
    [kind, key] = deal (tok{1}, tok{2});
    fmt = "%g";
    if (numel (tok) > 2 && ! isempty (tok{3}))
      fmt = tok{3}(2:end);
    endif
    s = s(e+1:end);
    switch (kind)
      case ""
        [v, found] = lookup (scopes, key);
        if (! found)
          error ("lafortune:badTemplate", "report_fill: no value for {{%s}}", key);
        endif
        out = [out text_of(v, fmt, key)];
      case ">"
        t = fill (read_template (d, key), scopes, d);
        if (! isempty (t) && t(end) == "\n")
          t(end) = [];                   # the tag's line ends it
        endif
        out = [out t];
      case "/"
        error ("lafortune:badTemplate", "report_fill: {{/%s}} closes no section", key);
      otherwise
        [inner, s] = section (s, key);
        v = lookup (scopes, key);          # [] when missing
        if (kind == "^")
          if (! truthy (v))
            out = [out fill(inner, scopes, d)];
          endif
        elseif (truthy (v))
          if (isstruct (v))
            v = num2cell (v);
          elseif (! iscell (v))
            v = {struct()};
          endif
          for k = 1:numel (v)
            item = v{k};
            if (! isstruct (item))
              item = struct ("item_", {item});
            endif
            out = [out fill(inner, [scopes, {item}], d)];
          endfor
        endif
    endswitch
  endwhile
endfunction

## the block of section KEY up to its closing tag, and what follows it
function [inner, rest] = section (s, key)
  depth = 1;
  pos = 1;
  pat = ['\{\{([#^/])\s*' regexptranslate("escape", key) '\s*\}\}'];
  while (true)
    [tok, b, e] = regexp (s(pos:end), pat, "tokens", "start", "end", "once");
    if (isempty (tok))
      error ("lafortune:badTemplate", "report_fill: section {{#%s}} is not closed", key);
    endif
    depth += merge (tok{1} == "/", -1, 1);
    if (depth == 0)
      inner = s(1:pos+b-2);
      rest = s(pos+e:end);
      return;
    endif
    pos += e;
  endwhile
endfunction

## the value of KEY (a field, or a path x.y) in the innermost scope that
## has its first name; FOUND is false when that scope lacks the rest of it
function [v, found] = lookup (scopes, key)
  parts = strsplit (key, ".");
  if (strcmp (key, "."))
    parts = {"item_"};
  endif
  v = [];
  found = false;
  for k = numel (scopes):-1:1
    if (isfield (scopes{k}, parts{1}))
      v = scopes{k}.(parts{1});
      for p = parts(2:end)
        if (! isstruct (v) || ! isfield (v, p{1}))
          v = [];
          return;
        endif
        v = v.(p{1});
      endfor
      found = true;
      return;
    endif
  endfor
endfunction

function tf = truthy (v)
  tf = ! isempty (v) && ! ((isnumeric (v) || islogical (v)) && isscalar (v) && ! v);
endfunction

function s = text_of (v, fmt, key)
  if (ischar (v))
    s = v;
  elseif (iscellstr (v))
    s = strjoin (v, ", ");
  elseif (islogical (v) && ! isempty (v))
    s = strjoin (arrayfun (@(x) merge (x, "yes", "no"), v(:)', "uniformoutput", false), " / ");
  elseif (isnumeric (v) || islogical (v))
    c = arrayfun (@(x) sprintf (fmt, x), double (v(:)'), "uniformoutput", false);
    c(isnan (v(:)')) = {"-"};
    s = strjoin (c, " / ");
    if (isempty (v))
      s = "-";
    endif
  else
    error ("lafortune:badTemplate", "report_fill: {{%s}} is a %s: expected text or numbers", key, class (v));
  endif
endfunction

