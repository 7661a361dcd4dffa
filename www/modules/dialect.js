// The control a program names by its dialect (issue 34, behaviour 22.8):
// LinuxCNC's o-words (`o100 sub`, `o<name> call`) and named parameters
// (`#<depth>`) are written by no Fanuc-family control. A `;` alone names
// nothing: Fanuc programs write it as the end of block.

const OWORD = /^[ \t]*o[ \t]*(?:\d+|<[^>\r\n]*>)[ \t]*(?:sub|call|if|while|do|repeat)\b/im;
const NAMED = /#<[^>\r\n]+>/;

/** How much of a program's start is looked at. */
const HEAD = 256 * 1024;

/** 'linuxcnc' and what says so when `text` is written for LinuxCNC, else null. */
export function dialectOf(text) {
  const head = text.slice(0, HEAD);
  const oword = head.match(OWORD);
  if (oword) return { control: 'linuxcnc', why: `its o-word “${oword[0].trim()}”` };
  const named = head.match(NAMED);
  if (named) return { control: 'linuxcnc', why: `its named parameter “${named[0]}”` };
  return null;
}
