package org.libmoa;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/**
 * Loads the JNI library libmoa_java before the first native call. Looks, in order: at the path in
 * the system property {@code org.libmoa.library}; beside the jar holding this class (the build
 * tree); in the folder the install rules put it in, relative to the jar (recorded in
 * library.properties when the jar was built); and on {@code java.library.path}.
 */
final class NativeLibrary {
  private static final String NAME = "moa_java";

  private NativeLibrary() {}

  static void load() {
    String explicit = System.getProperty("org.libmoa.library");
    if (explicit != null && !explicit.isEmpty()) {
      System.load(new File(explicit).getAbsolutePath());
      return;
    }
    File jarDir = jarDirectory();
    if (jarDir != null) {
      String file = System.mapLibraryName(NAME);
      String[] candidates = {".", installedRelativeDir()};
      for (String dir : candidates) {
        File library = new File(new File(jarDir, dir), file);
        if (dir != null && library.isFile()) {
          System.load(library.getAbsolutePath());
          return;
        }
      }
    }
    System.loadLibrary(NAME);
  }

  private static File jarDirectory() {
    try {
      java.security.CodeSource source = NativeLibrary.class.getProtectionDomain().getCodeSource();
      if (source == null) return null;
      File location = new File(source.getLocation().toURI());
      return location.isFile() ? location.getParentFile() : null;
    } catch (Exception e) {  // no file location (e.g. a custom class loader): skip the search
      return null;
    }
  }

  private static String installedRelativeDir() {
    try (InputStream in = NativeLibrary.class.getResourceAsStream("library.properties")) {
      if (in == null) return null;
      Properties p = new Properties();
      p.load(in);
      return p.getProperty("installed.jni.dir");
    } catch (IOException e) {
      return null;
    }
  }
}
