## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Tests of scripts/report_fill.m, the reports' template filler: values and
## their formats, sections over lists and conditions, inverted sections,
## partials, section tags on lines of their own, and the errors.

%!shared top, d
%! top = fileparts (fileparts (mfilename ("fullpath")));
%! if (isempty (top) || ! exist (fullfile (top, "scripts", "report_fill.m"), "file"))
%!   top = pwd ();
%! endif
%! addpath (fullfile (top, "scripts"));
%! d = tempname (); mkdir (d);

%!function put (d, name, txt)
%!  fid = fopen (fullfile (d, [name ".md"]), "w"); fputs (fid, txt); fclose (fid);
%!endfunction

%!test
%! ## values: text, numbers with a format, arrays, NaN, lists, logicals, paths
%! put (d, "a", "t={{t}} x={{x|%.2f}} v={{v|%.1f}} n={{n}} e={{e}} c={{c}} y={{y}} p={{s.q}}\n");
%! V = struct ("t", "hi", "x", pi, "v", [1 NaN 3], "n", 7, "e", [], "c", {{"a", "b"}}, "y", true,
%!             "s", struct ("q", "deep"));
%! assert (report_fill (fullfile (d, "a.md"), V), "t=hi x=3.14 v=1.0 / - / 3.0 n=7 e=- c=a, b y=yes p=deep\n");

%!test
%! ## a table: header, the rows of a struct array (section tags on lines of
%! ## their own leave no line), the outer scope seen from inside
%! put (d, "b", "| m | k |\n|---|---|\n{{#rows}}\n| {{m}} | {{k|%d}}{{u}} |\n{{/rows}}\nend\n");
%! V = struct ("u", "!", "rows", struct ("m", {"x", "y"}, "k", {1, 2}));
%! assert (report_fill (fullfile (d, "b.md"), V), "| m | k |\n|---|---|\n| x | 1! |\n| y | 2! |\nend\n");

%!test
%! ## conditions, inverted sections, inline sections, a list of texts, nesting
%! put (d, "c", "{{#on}}yes{{/on}}{{^on}}no{{/on}} [{{#L}}<{{.}}>{{/L}}] {{#o}}{{#i}}{{k}}{{/i}};{{/o}}{{^miss}}!{{/miss}}\n");
%! o = {struct("i", struct ("k", {1, 2})), struct("i", struct ("k", {3}))};
%! assert (report_fill (fullfile (d, "c.md"), struct ("on", 0, "L", {{"p", "q"}}, "o", {o})), "no [<p><q>] 12;3;!\n");
%! assert (report_fill (fullfile (d, "c.md"), struct ("on", true, "L", {{}}, "o", {{}})), "yes [] !\n");

%!test
%! ## a partial, filled in the same scope
%! put (d, "part", "(part {{t}})\n");
%! put (d, "main", "a\n{{>part}}\nb\n");
%! assert (report_fill (fullfile (d, "main.md"), struct ("t", 1)), "a\n(part 1)\nb\n");
%! ## a partial that ends with a blank line keeps it (one end of line is the tag's)
%! put (d, "part2", "x\n\n");
%! put (d, "main2", "{{>part2}}\ny\n");
%! assert (report_fill (fullfile (d, "main2.md"), struct ()), "x\n\ny\n");

%!test
%! ## the pipeline's templates exist and name only what their reports give
%! f = glob (fullfile (top, "scripts", "templates", "*.md"));
%! assert (numel (f) >= 3);

%!error <no value for \{\{zz\}\}> put (d, "e1", "{{zz}}"), report_fill (fullfile (d, "e1.md"), struct ())
%!error <is not closed> put (d, "e2", "{{#a}}x"), report_fill (fullfile (d, "e2.md"), struct ("a", 1))
%!error <closes no section> put (d, "e3", "x{{/a}}"), report_fill (fullfile (d, "e3.md"), struct ("a", 1))
%!error <no template> report_fill (fullfile (d, "none.md"), struct ())
%!error <expected text or numbers> put (d, "e4", "{{a}}"), report_fill (fullfile (d, "e4.md"), struct ("a", struct ()))
