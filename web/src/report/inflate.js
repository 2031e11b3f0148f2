// The binaries the page carries (glTF files, recorded frames) are gzip-compressed and in base64
// (harness/report/html/report_data.h); the browser inflates them itself, with nothing fetched.

/** The bytes of base64 text `text`. */
export function base64Bytes(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** The bytes packed in `text` (gzip, then base64), as a promise of a Uint8Array. */
export async function unpack(text) {
  const stream = new Blob([base64Bytes(text)]).stream().pipeThrough(new DecompressionStream("gzip"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}
