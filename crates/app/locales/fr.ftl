# Zeta Lab — français. Ids and variables as in en.ftl.

## La page

page-skip = Aller à la démonstration
page-demo = Démonstration
page-share = Partager / Intégrer
page-loading = Chargement du solveur…
page-footer = Zeta Lab — chaque nombre de cette page est calculé en Rust (compilé en WebAssembly) à partir de solutions exactes.
page-parameters = Paramètres
page-readouts = Résultats
page-about = À propos de cette démonstration
page-plot-in-view = Graphique affiché
page-presets = Préréglages
page-reset = Valeurs par défaut
page-exact-value = valeur exacte
page-export-group = Exporter { $plot }
page-download = Télécharger { $plot } en { $format }
page-play = Lecture
page-pause = Pause
page-sound-on = Son activé
page-sound-off = Son coupé
page-sound-hint = Écouter x(t) : la hauteur du son suit le déplacement
page-anim-time = Temps de l’animation
page-time-words = temps { $t } secondes
page-schematic = Schéma animé
page-dismiss = Fermer l’avis
page-failed = Une erreur s’est produite et la démonstration a été relancée : { $text }
page-no-demo = Il n’existe pas de démonstration « { $id } » ; affichage de { $fallback }.
page-no-wasm = Le solveur n’a pas pu être chargé ({ $text }). Cette page nécessite WebAssembly.
page-copy = Copier
page-equation = Équation
page-tour-head = L’article, figure par figure
page-tour-open = Ouvrir cet état dans la démonstration
page-tour-paper = L’article indique
page-tour-app = L’application calcule
page-tour-confirmed = Confirmé.
page-tour-differs = Diffère.
page-copied = Copié
page-copy-manual = Sélectionnez et copiez (Ctrl+C)
page-share-title = Partager ou intégrer « { $title } »
page-embed-view = {" "}Vue intégrée (sans en-tête du site)
page-autoplay = {" "}Lancer l’animation
page-theme = Thème{" "}
page-width = {" "}Largeur{" "}
page-height = {" "}Hauteur{" "}
page-sliders-shown = Curseurs affichés
page-sliders-locked = Curseurs verrouillés
page-plots-shown = Graphiques affichés
page-link = Lien
page-embed-code = Code d’intégration
page-preview = Aperçu de la démonstration intégrée
page-close = Fermer
page-language = Langue
page-language-nav = Langue
page-demos-nav = Démonstrations
page-no-script = Zeta Lab nécessite JavaScript et WebAssembly.
page-catalogue-failed = Le catalogue { $name } n’a pas pu être chargé ({ $text }) ; la page reste en anglais.
page-provisional = { $value } (provisoire)
page-readouts-shown = Résultats affichés
page-state-token = Jeton d’état
page-theme-auto = automatique
page-theme-light = clair
page-theme-dark = sombre
page-theme-projector = projecteur (contraste élevé)
page-share-visitor-language = langue du visiteur
page-share-language = {" "}Langue{" "}
page-share-fullscreen = {" "}Bouton plein écran
page-share-ranges = Plages et pas des curseurs (laisser vide pour garder ceux déclarés)
page-share-col-slider = curseur
page-share-col-from = de
page-share-col-to = à
page-share-col-step = pas
page-share-range-from = { $label } : minimum
page-share-range-to = { $label } : maximum
page-share-range-step = { $label } : pas
page-share-predict-task = Exercice de prédiction
page-share-none = aucun
page-share-predict = Les étudiants prédisent{" "}
page-share-predict-within = {" "}avec une tolérance de{" "}
page-share-presets = Préréglages de l’enseignant (inclus dans le lien)
page-share-preset-example = p. ex. Amortissement faible
page-share-preset-add = Ajouter les valeurs affichées
page-share-preset-format = Format : nom:clé=valeur,clé=valeur; autre nom:…
page-share-preset-default = Préréglage { $n }
page-share-preset-name = Nom{" "}
page-share-preset-list = Préréglages{" "}
page-lecturer-presets = Préréglages de l’enseignant
page-full-screen = Plein écran
page-exit-full-screen = Quitter le plein écran
page-no-stamp = Ce fichier ne contient aucune vue Zeta Lab (seuls les PNG, SVG et CSV exportés par Zeta Lab en contiennent).
page-token-invalid = Cette vue enregistrée n’est pas un jeton d’état Zeta Lab.
page-token-version = Cette vue enregistrée a la version de format « { $version } », que cette page ne sait pas lire ; rien n’a été modifié.
page-token-damaged = Cette vue enregistrée est endommagée et illisible ; rien n’a été modifié.
page-token-no-demo = Cette vue enregistrée désigne une démonstration que cette page n’a pas (« { $demo } ») ; rien n’a été modifié.
page-token-other-version-missing = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $n ->
        [one] { $missing } n’y figure pas et prend la valeur par défaut.
       *[other] { $missing } n’y figurent pas et prennent la valeur par défaut.
    }
page-token-other-version-unknown = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $m ->
        [one] { $unknown } est inconnu ici et a été ignoré.
       *[other] { $unknown } sont inconnus ici et ont été ignorés.
    }
page-token-other-version-both = Cette vue enregistrée provient d’une autre version de Zeta Lab : { $n ->
        [one] { $missing } n’y figure pas et prend la valeur par défaut
       *[other] { $missing } n’y figurent pas et prennent la valeur par défaut
    } ; { $m ->
        [one] { $unknown } est inconnu ici et a été ignoré.
       *[other] { $unknown } sont inconnus ici et ont été ignorés.
    }
page-predict-title = D’abord, prédire
page-predict-hint = Les graphiques et la grandeur « { $label } » restent masqués jusqu’à votre prédiction. Saisissez-la et appuyez sur Entrée.
page-predict-field = Votre prédiction de « { $label } »
page-predict-field-unit = Votre prédiction de « { $label } » ({ $unit })
page-predict-reveal = Révéler
page-predict-nan = « { $text } » n’est pas un nombre. Saisissez un nombre comme { $example }.
page-predict-undefined = « { $label } » n’est pas défini pour ces paramètres ; modifiez-les et réessayez.
page-predict-result-inside = Vous avez prédit { $p } ; « { $label } » vaut { $v } : { $how }, dans la tolérance de { $tol }.
page-predict-result-outside = Vous avez prédit { $p } ; « { $label } » vaut { $v } : { $how }, hors de la tolérance de { $tol }.
page-predict-exact = exactement juste
page-predict-high = trop élevée de { $d }
page-predict-low = trop basse de { $d }

## Graphiques

plot-clipped = tronqué : certaines valeurs dépassent les axes

## Mots partagés : axes, régimes

axis-time = temps t
axis-displacement = déplacement x
axis-extension = allongement x
axis-force = force F
axis-velocity = vitesse v
axis-real-part = partie réelle Re s
axis-imaginary-part = partie imaginaire Im s
regime-undamped = non amorti
regime-underdamped = sous-amorti
regime-critically-damped = amortissement critique
regime-overdamped = suramorti
regime-negatively-damped = amortissement négatif
regime-neutral = neutre
regime-divergent = divergent

## Démonstrations
