## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} __lafortune_write__ (@var{file}, @var{who}, @var{writer})
## @deftypefnx {} {} __lafortune_write__ (@var{file}, @var{who}, @var{writer}, @var{arch})
## @deftypefnx {} {} __lafortune_write__ (@var{file}, @var{who}, "text", @var{txt})
## @deftypefnx {} {} __lafortune_write__ (@var{file}, @var{who}, "file", @var{writer})
## The package's one atomic write (internal, for its functions and the
## pipeline's scripts): @var{file} is written through a temporary file in
## its folder (a name with @file{.tmp} in it, the extension kept), which is
## renamed onto @var{file} only when it is complete.  On any failure the
## temporary file is removed, an earlier @var{file} is left as it was, and
## the error is @code{lafortune:unwritable}, its message starting with
## @var{who} (or the writer's own error, with its own id).
##
## @table @asis
## @item @var{writer} (a function handle)
## called as @code{nbytes = writer (fid)} on the open temporary file
## (@var{arch}: fopen's byte order, default "native"); it returns the
## number of bytes it wrote, negative when it saw a failure.  The file must
## have exactly that size: Octave's fwrite, fputs and fclose do not report
## a disk that refuses the data (full, or over a size limit).
## @item "text"
## @var{txt} (a string, or a cell array of strings written one after the
## other), by @code{fputs}, its size checked the same way.
## @item "file"
## @var{writer} is called as @code{writer (tmp)} with the temporary file's
## name, for a writer that opens the file itself (@code{print},
## @code{imwrite}, @code{copyfile}); the file must not be empty.  An error
## of the writer becomes @code{lafortune:unwritable}.
## @end table
##
## The folder of @var{file} must exist.
##
## @example
## @group
## __lafortune_write__ ("notes.txt", "myscript", "text", @{"line 1\n", "line 2\n"@});
## __lafortune_write__ ("x.bin", "myscript", @@(fid) 8 * fwrite (fid, pi, "double"), "ieee-le");
## __lafortune_write__ ("f.png", "myscript", "file", @@(tmp) print (gcf, "-dpng", tmp));
## @end group
## @end example
## @end deftypefn

function __lafortune_write__ (file, who, writer, arg)
  if (nargin < 3 || nargin > 4)
    print_usage ();
  endif
  if (! ischar (who))
    error ("lafortune:badArgument", "__lafortune_write__: WHO must be a function's name");
  endif
  mode = "fid";
  arch = "native";
  if (ischar (writer))
    mode = writer;
    if (nargin < 4 || ! any (strcmp (mode, {"text", "file"})))
      error ("lafortune:badArgument",
             "__lafortune_write__: expected a writer, \"text\" with the text, or \"file\" with a writer");
    endif
    if (strcmp (mode, "text"))
      txt = arg;
      if (ischar (txt))
        txt = {txt};
      endif
      if (! iscellstr (txt))
        error ("lafortune:badArgument", "%s: the text to write must be a string or a cell of strings",
               who);
      endif
      writer = @(fid) put_text (fid, txt);
      mode = "fid";
    else
      writer = arg;
    endif
  elseif (nargin == 4)
    arch = arg;
  endif
  if (! is_function_handle (writer))
    error ("lafortune:badArgument", "__lafortune_write__: WRITER must be a function handle");
  endif
  tmp = temp_name (file, who);
  ok = false;
  unwind_protect
    if (strcmp (mode, "fid"))
      fid = fopen (tmp, "w", arch);
      if (fid < 0)
        error ("lafortune:unwritable", "%s: cannot write '%s'", who, tmp);
      endif
      try
        nbytes = writer (fid);
      catch err
        fclose (fid);
        rethrow (err);
      end_try_catch
      st = fclose (fid);
      [info, err] = stat (tmp);
      if (st != 0 || nbytes < 0 || err != 0 || info.size != nbytes)
        error ("lafortune:unwritable", "%s: writing '%s' failed (disk full or a file size limit?)",
               who, file);
      endif
    else
      try
        writer (tmp);
      catch err
        error ("lafortune:unwritable", "%s: cannot write '%s': %s", who, file, err.message);
      end_try_catch
      s = dir (tmp);
      if (isempty (s) || s.bytes == 0)
        error ("lafortune:unwritable", "%s: writing '%s' gave an empty file (disk full?)",
               who, file);
      endif
    endif
    [err, msg] = rename (tmp, file);
    if (err)
      error ("lafortune:unwritable", "%s: cannot replace '%s': %s", who, file, msg);
    endif
    ok = true;
  unwind_protect_cleanup
    if (! ok && exist (tmp, "file"))
      unlink (tmp);
    endif
  end_unwind_protect
endfunction

## a new empty file beside FILE, named after it, for the write
function tmp = temp_name (file, who)
  if (! ischar (file) || isempty (file) || rows (file) != 1)
    error ("lafortune:badFile", "%s: FILE must be a non-empty string", who);
  endif
  [d, b, e] = fileparts (file);
  if (isempty (d))
    d = ".";
  endif
  if (! isfolder (d))
    error ("lafortune:unwritable", "%s: cannot write '%s': folder '%s' does not exist",
           who, file, d);
  endif
  if (isfolder (file))
    error ("lafortune:unwritable", "%s: cannot write '%s': it is a folder", who, file);
  endif
  tmp = fullfile (d, sprintf (".%s.tmp%d%06d%s", b, getpid (), randi (999999), e));
  [fid, msg] = fopen (tmp, "w");
  if (fid < 0)
    error ("lafortune:unwritable", "%s: cannot write in folder '%s': %s", who, d, msg);
  endif
  fclose (fid);
endfunction

## the strings of TXT one after the other: the bytes written, -1 when fputs failed
function nbytes = put_text (fid, txt)
  nbytes = 0;
  for k = 1:numel (txt)
    if (fputs (fid, txt{k}) != 0)
      nbytes = -1;
      return;
    endif
    nbytes += numel (txt{k});
  endfor
endfunction

%!function copy_checked (src, tmp)
%!  assert (! isempty (regexp (tmp, '\.tmp[0-9]+\.json$', "once")), tmp);
%!  copyfile (src, tmp);
%!endfunction

%!shared d
%! d = tempname (); mkdir (d);

%!test
%! f = fullfile (d, "a.txt");
%! __lafortune_write__ (f, "t", "text", {"one\n", "two\n"});
%! assert (fileread (f), "one\ntwo\n");
%! __lafortune_write__ (f, "t", "text", "three\n");
%! assert (fileread (f), "three\n");
%! assert (numel (dir (d)), 3);                         # ., .., a.txt: no temporary left

%!test
%! f = fullfile (d, "b.bin");
%! __lafortune_write__ (f, "t", @(fid) 4 * fwrite (fid, int32 (258), "int32"), "ieee-be");
%! fid = fopen (f, "r"); b = fread (fid, Inf, "uint8")'; fclose (fid);
%! assert (b, [0 0 1 2]);

%!test
%! ## a writer that opens the file itself; the extension is kept
%! f = fullfile (d, "c.json");
%! __lafortune_write__ (f, "t", "file", @(tmp) copy_checked (fullfile (d, "a.txt"), tmp));
%! assert (fileread (f), "three\n");

%!test
%! ## failures: the old file stays, no temporary file is left, the error says who
%! f = fullfile (d, "a.txt");
%! try
%!   __lafortune_write__ (f, "mine", @(fid) fputs (fid, "partial") + 100);
%!   error ("no error");
%! catch err
%!   assert (err.identifier, "lafortune:unwritable");
%!   assert (strncmp (err.message, "mine: writing", 13), err.message);
%! end_try_catch
%! try
%!   __lafortune_write__ (f, "mine", @(fid) error ("own:id", "the writer's own"));
%!   error ("no error");
%! catch err
%!   assert (err.identifier, "own:id");
%! end_try_catch
%! try
%!   __lafortune_write__ (f, "mine", "file", @(tmp) error ("own:id", "cannot"));
%!   error ("no error");
%! catch err
%!   assert (err.identifier, "lafortune:unwritable");
%!   assert (! isempty (strfind (err.message, "cannot")));
%! end_try_catch
%! try
%!   __lafortune_write__ (f, "mine", "file", @(tmp) true);      # leaves the file empty
%!   error ("no error");
%! catch err
%!   assert (err.identifier, "lafortune:unwritable");
%! end_try_catch
%! assert (fileread (f), "three\n");
%! n = {dir(d).name};
%! assert (isempty (regexp (strjoin (n, " "), '\.tmp', "once")), strjoin (n, " "));

%!error id=lafortune:unwritable __lafortune_write__ (fullfile (tempname (), "x.txt"), "t", "text", "x")
%!error id=lafortune:unwritable __lafortune_write__ (tempdir, "t", "text", "x")
%!error id=lafortune:badFile __lafortune_write__ ("", "t", "text", "x")
%!error id=lafortune:badArgument __lafortune_write__ ("x.txt", "t", "print", "x")
%!error id=lafortune:badArgument __lafortune_write__ ("x.txt", "t", "text", 3)
%!error id=lafortune:badArgument __lafortune_write__ ("x.txt", "t", 3)
%!error <Invalid call> __lafortune_write__ ("x.txt", "t")

%!test
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
