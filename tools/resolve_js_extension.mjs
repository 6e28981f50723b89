// A Node.js module resolve hook: cityjson-threejs-loader is written for
// bundlers and imports its own files (and three's examples) without the ".js"
// extension, which Node's ES module loader requires. This retries such an
// import with ".js" added, so the package runs unchanged under Node.
export async function resolve(specifier, context, next) {
  try {
    return await next(specifier, context);
  } catch (error) {
    if (error.code !== 'ERR_MODULE_NOT_FOUND' || specifier.endsWith('.js')) throw error;
    return next(specifier + '.js', context);
  }
}
