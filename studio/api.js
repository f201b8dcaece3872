// The studio's JSON API: every error comes back as {"error": message}.

/** Fetches JSON; throws an Error carrying the server's message. */
export async function call(url, options = {}) {
  const response = await fetch(url, options);
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

/** Uploads a File; resolves to the pattern view with its document id. */
export function upload(file) {
  return call(`/api/upload?name=${encodeURIComponent(file.name)}`, { method: 'POST', body: file });
}
