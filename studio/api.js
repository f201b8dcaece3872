// The studio's JSON API: every error comes back as {"error": message}.

/** This launch's token, written into the page by the server: the studio refuses requests that
 * change something without it (other web pages cannot read the page to learn it). */
const TOKEN = document.querySelector('meta[name="foldcam-token"]')?.content ?? '';

/** A whole JSON reply's body; throws an Error carrying the server's message when the reply
 * is a refusal or not JSON. */
async function jsonBody(url, response) {
  const text = await response.text();
  let body;
  try {
    body = JSON.parse(text);
  } catch {
    throw new Error(`${url}: ${response.status} ${text.slice(0, 200)}`);
  }
  if (!response.ok) throw new Error(body.error || `${url}: ${response.status}`);
  return body;
}

/** Fetches JSON with the page's token; throws an Error carrying the server's message. */
export async function call(url, options = {}) {
  const headers = { ...(options.headers || {}), 'x-foldcam-token': TOKEN };
  return jsonBody(url, await fetch(url, { ...options, headers }));
}

/** Reads a newline-delimited JSON reply (the API's `stream=true` routes), calling `onLine`
 * with each line as it arrives; resolves when the reply ends. A refusal throws as `call`'s. */
export async function stream(url, onLine) {
  const response = await fetch(url, { headers: { 'x-foldcam-token': TOKEN } });
  if (!response.ok) await jsonBody(url, response);
  const reader = response.body.getReader();
  const decoder = new TextDecoder();
  let buffered = '';
  for (;;) {
    const { value, done } = await reader.read();
    if (value) buffered += decoder.decode(value, { stream: true });
    let end;
    while ((end = buffered.indexOf('\n')) >= 0) {
      const line = buffered.slice(0, end);
      buffered = buffered.slice(end + 1);
      if (line.trim()) onLine(JSON.parse(line));
    }
    if (done) break;
  }
  if (buffered.trim()) onLine(JSON.parse(buffered));
}

/** The file of a set to open: a paper-craft or tessellation design (its mesh comes with it),
 * else the first. */
export function mainFile(files) {
  return files.find((f) => /\.(craft|tess)\.toml$/i.test(f.name)) || files[0];
}

/** Uploads the files dropped or picked together: the main one is opened, the others go with
 * it in the same body (a paper craft's mesh). `make` says what a mesh becomes. Resolves to
 * the pattern view with its document id. */
export function upload(files, make = 'auto') {
  const main = mainFile(files);
  const others = files.filter((f) => f !== main);
  let url = `/api/upload?name=${encodeURIComponent(main.name)}&make=${encodeURIComponent(make)}`;
  if (others.length) {
    const parts = others.map((f) => ({ name: f.name, size: f.size }));
    url += `&with=${encodeURIComponent(JSON.stringify(parts))}`;
  }
  return call(url, { method: 'POST', body: new Blob([main, ...others]) });
}
