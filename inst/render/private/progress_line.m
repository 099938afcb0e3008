## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} progress_line (@var{name})
## @deftypefnx {} {@var{p} =} progress_line (@var{name}, @var{where})
## @deftypefnx {} {@var{p} =} progress_line (@var{p}, @var{fraction})
## @deftypefnx {} {@var{p} =} progress_line (@var{p}, @var{fraction}, @var{elapsed})
## @deftypefnx {} {@var{p} =} progress_line (@var{p}, "done")
## The one printer of progress lines (private): "NAME: 42% done, 12 s left".
##
## @code{progress_line (@var{name})} starts a report and returns its state;
## nothing is printed for work that ends within @code{p.quiet} = 2 s.
## @code{progress_line (@var{p}, @var{fraction})} reports that
## @var{fraction} (0 to 1) is done; @code{progress_line (@var{p}, "done")}
## ends the report ("NAME: 100% done in 12.3 s", only if something was
## printed).
##
## On a terminal the line is rewritten in place (a carriage return, at most
## every 0.5 s).  Otherwise (stdout is a file or a pipe, e.g. @code{make
## reproduce > log}, or the GUI's command window) a whole line is printed
## each time the work passes a multiple of 10%, or 30 s after the last line,
## with no carriage returns.  @var{where} (@qcode{"auto"}, default,
## @qcode{"tty"} or @qcode{"log"}) forces one of the two; @var{elapsed}
## (seconds) replaces the clock (for tests).
## @end deftypefn
function p = progress_line (p, fraction, elapsed)
  if (ischar (p))
    where = "auto";
    if (nargin > 1)
      where = fraction;
    endif
    if (strcmp (where, "auto"))
      tty = on_terminal ();
    else
      tty = strcmp (where, "tty");
    endif
    p = struct ("name", p, "tty", tty, "t0", tic (), "quiet", 2,
                "last", -Inf, "decile", 0, "printed", false);
    return;
  endif
  if (nargin < 3)
    elapsed = toc (p.t0);
  endif
  if (ischar (fraction))                # "done"
    if (p.printed)
      emit (p.tty, sprintf ("%s: 100%% done in %.1f s", p.name, elapsed), "          \n");
    endif
    return;
  endif
  if (elapsed <= p.quiet || fraction <= 0)
    return;
  endif
  decile = floor (10 * fraction + 1e-9);
  if (p.tty)
    due = elapsed - p.last > 0.5;
  else
    ## (100% is said by the "done" line)
    due = fraction < 1 && (decile > p.decile || elapsed - p.last >= 30);
  endif
  if (! due)
    return;
  endif
  emit (p.tty, sprintf ("%s: %3.0f%% done, %5.0f s left", p.name, 100 * fraction,
                        elapsed * (1 - fraction) / fraction), " ");
  p.last = elapsed;
  p.decile = max (p.decile, decile);
  p.printed = true;
endfunction

## true when stdout is a terminal (and not the GUI's command window)
function tty = on_terminal ()
  persistent cached;
  if (isempty (cached))
    cached = ! isguirunning () && system ("test -t 1", false) == 0;
  endif
  tty = cached;
endfunction

## One line: on a terminal rewritten in place (a carriage return first, then
## TTY_END), else a line of its own.
function emit (tty, txt, tty_end)
  if (tty)
    fprintf ("\r%s%s", txt, tty_end);
  else
    fprintf ("%s\n", txt);
  endif
  fflush (stdout);
endfunction
